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
# The default scene again with Holographic Radiance Cascades, next to the reference, and the error.
size=$("$luxel" info "scenes/2d/$default_scene.json" | awk '/canvas/ {print $2; exit}')
start=$(date +%s%N)
"$luxel" render "scenes/2d/$default_scene.json" --solver hrc --quiet \
  --out "out/$default_scene-hrc.exr" --png "out/$default_scene-hrc.png"
ms=$(( ($(date +%s%N) - start) / 1000000 ))
printf '%-14s %-10s %4d.%02d    %s\n' "$default_scene (hrc)" "$size" $((ms / 1000)) \
  $((ms % 1000 / 10)) "out/$default_scene-hrc.exr out/$default_scene-hrc.png"
echo "hrc vs reference on $default_scene:"
"$luxel" compare "out/$default_scene-hrc.exr" "out/$default_scene.exr" \
  --diff "out/$default_scene-hrc-diff.png" | sed 's/^/  /'
echo "all 2D solvers on $default_scene (left to right in out/$default_scene-solvers.png:" \
  "reference, hrc, rc vanilla, rc bilinear fix):"
"$luxel" compare-solvers "scenes/2d/$default_scene.json" --grid "out/$default_scene-solvers.png" |
  sed 's/^/  /'
# The default voxel scene: terrain, shadows, reflections.
start=$(date +%s%N)
"$luxel" render scenes/voxel/terrain.json --quiet --out out/terrain.exr --png out/terrain.png
ms=$(( ($(date +%s%N) - start) / 1000000 ))
printf '%-14s %-10s %4d.%02d    %s\n' "terrain" "960x540" $((ms / 1000)) $((ms % 1000 / 10)) \
  "out/terrain.exr (radiance, linear) out/terrain.png (voxel ray casting)"
# Textured voxels: PNG textures, cutout leaves casting dappled shadows.
start=$(date +%s%N)
"$luxel" render scenes/voxel/garden.json --quiet --out out/garden.png
ms=$(( ($(date +%s%N) - start) / 1000000 ))
printf '%-14s %-10s %4d.%02d    %s\n' "garden" "960x540" $((ms / 1000)) $((ms % 1000 / 10)) \
  "out/garden.png (textures with cutouts)"
# Surfaces: glass (refraction, total internal reflection, Fresnel), a mirror wall, a lamp; bloom.
start=$(date +%s%N)
"$luxel" render scenes/voxel/glass.json --quiet --bloom 0.3 --samples 4 --out out/glass.png
ms=$(( ($(date +%s%N) - start) / 1000000 ))
printf '%-14s %-10s %4d.%02d    %s\n' "glass" "960x540" $((ms / 1000)) $((ms % 1000 / 10)) \
  "out/glass.png (physical lighting, 4 samples per pixel, bloom 0.3)"
# Soft sun shadows: the MRMA blend of moment shadow maps and distance-field shadows.
start=$(date +%s%N)
"$luxel" render scenes/voxel/fence.json --quiet --lighting physical --out out/fence.png
ms=$(( ($(date +%s%N) - start) / 1000000 ))
printf '%-14s %-10s %4d.%02d    %s\n' "fence" "480x270" $((ms / 1000)) $((ms % 1000 / 10)) \
  "out/fence.png (2-degree sun, MSM + SDF blend)"
# Post-processing: bloom, and half internal resolution with the edge-aware upscaler.
start=$(date +%s%N)
"$luxel" render scenes/voxel/terrain.json --quiet --bloom 0.3 \
  --internal-scale 0.5 --upscaler edge --out out/terrain-post.png
ms=$(( ($(date +%s%N) - start) / 1000000 ))
printf '%-14s %-10s %4d.%02d    %s\n' "terrain-post" "960x540" $((ms / 1000)) $((ms % 1000 / 10)) \
  "out/terrain-post.png (bloom 0.3, rendered at 480x270, edge-aware upscale)"
# Sparse voxel octrees: the terrain world as a DAG (surface, hard shadows), a CT-like phantom
# (translucent, scattering), and a 4096^3 terrain no dense grid could hold (soft shadows).
for name in world phantom terrain; do
  start=$(date +%s%N)
  "$luxel" render "scenes/octree/$name.json" --quiet --out "out/octree-$name.exr" \
    --png "out/octree-$name.png"
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  size=$("$luxel" info "scenes/octree/$name.json" | awk '/^  image/ {sub(",", "", $2); print $2; exit}')
  printf '%-14s %-10s %4d.%02d    %s\n' "octree $name" "$size" $((ms / 1000)) $((ms % 1000 / 10)) \
    "out/octree-$name.exr out/octree-$name.png"
done

# Reference renders double as the benchmark's error yardstick (bench/bench_cascades2d.cpp).
mkdir -p out/reference-cache
cp "out/$default_scene.exr" "out/reference-cache/${default_scene}_$size.exr"

total_ms=$(( ($(date +%s%N) - total_start) / 1000000 ))
printf 'total %d.%01d s; default scene: out/%s.png\n' $((total_ms / 1000)) $((total_ms % 1000 / 100)) \
  "$default_scene"
