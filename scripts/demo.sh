#!/usr/bin/env bash
# `make demo`: renders the shipped 2D scenes with the reference solver into out/.
# The default scene (room) first; then the others. Prints what was written and how long it took.
set -euo pipefail
build=${1:-build/release}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
luxel="$build/apps/cli/luxel"
mkdir -p out

default_scene=room
scenes=("$default_scene" penumbra pinhole fog thin-walls many-lights)

printf '%-14s %-10s %-9s %s\n' scene size seconds written
total_start=$(date +%s%N)
for name in "${scenes[@]}"; do
  start=$(date +%s%N)
  "$luxel" render "scenes/2d/$name.json" --solver reference --quiet \
    --out "out/$name.exr" --png "out/$name.png"
  end=$(date +%s%N)
  size=$("$luxel" info "scenes/2d/$name.json" | awk '/canvas/ {print $2; exit}')
  ms=$(( (end - start) / 1000000 ))
  printf '%-14s %-10s %4d.%02d    %s\n' "$name" "$size" $((ms / 1000)) $((ms % 1000 / 10)) \
    "out/$name.exr (fluence, linear) out/$name.png (display)"
done
total_ms=$(( ($(date +%s%N) - total_start) / 1000000 ))
printf 'total %d.%01d s; default scene: out/%s.png\n' $((total_ms / 1000)) $((total_ms % 1000 / 100)) \
  "$default_scene"
