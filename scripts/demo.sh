#!/usr/bin/env bash
# `make demo`: renders the shipped scenes into out/ and says what to open. The default 2D scene
# (room) with the reference solver at 1024 rays per pixel, the other 2D scenes with fewer rays
# (enough for their pictures), room again with HRC and every solver against the reference
# already rendered (compare-solvers --reference: nothing is rendered twice), then the voxel and
# octree scenes. Every image carries its provenance (`luxel info out/room.png`).
set -euo pipefail
build=${1:-build/release}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
luxel="$build/apps/cli/luxel"
mkdir -p out

default_scene=room
# name:rays. Room is the picture the others are measured against; soft shadows (penumbra) need
# more rays than hard edges and fog to look clean.
scenes_2d=("$default_scene:1024" penumbra:256 pinhole:128 fog:128 thin-walls:128 many-lights:128)

ms_since() { echo $(( ($(date +%s%N) - $1) / 1000000 )); }
row() {  # scene solver rays size ms written
  printf '%-14s %-10s %6s  %-9s %4d.%02d  %s\n' "$1" "$2" "$3" "$4" $(($5 / 1000)) \
    $(($5 % 1000 / 10)) "$6"
}
canvas() { "$luxel" info "scenes/2d/$1.json" | awk '/canvas/ {print $2; exit}'; }

total_start=$(date +%s%N)
printf '%-14s %-10s %6s  %-9s %7s  %s\n' scene solver rays size seconds written
for entry in "${scenes_2d[@]}"; do
  name=${entry%%:*} rays=${entry##*:}
  start=$(date +%s%N)
  "$luxel" render "scenes/2d/$name.json" --solver reference --rays "$rays" --quiet \
    --out "out/$name.exr" --png "out/$name.png"
  row "$name" reference "$rays" "$(canvas "$name")" "$(ms_since "$start")" \
    "out/$name.exr (fluence, linear) out/$name.png (display)"
done
# The default scene with Holographic Radiance Cascades, against the reference just rendered.
size=$(canvas "$default_scene")
start=$(date +%s%N)
"$luxel" render "scenes/2d/$default_scene.json" --solver hrc --quiet \
  --out "out/$default_scene-hrc.exr" --png "out/$default_scene-hrc.png"
row "$default_scene" hrc - "$size" "$(ms_since "$start")" \
  "out/$default_scene-hrc.exr out/$default_scene-hrc.png"
# Voxel scenes: terrain (shadows, reflections), textures with cutouts, glass (refraction,
# Fresnel, bloom), a 2-degree sun's soft shadows, and post-processing (bloom, half-resolution
# rendering with the edge-aware upscaler).
voxel_row() {  # name size output description, then the render flags
  local name=$1 vsize=$2 output=$3 what=$4
  shift 4
  start=$(date +%s%N)
  "$luxel" render "scenes/voxel/$name.json" --quiet "$@"
  row "$output" voxel - "$vsize" "$(ms_since "$start")" "out/$output.png ($what)"
}
voxel_row terrain 960x540 terrain "voxel ray casting; radiance in out/terrain.exr" \
  --out out/terrain.exr --png out/terrain.png
voxel_row terrain-evening 960x540 terrain-evening "a low sun under a Preetham clear sky" \
  --png out/terrain-evening.png
voxel_row garden 960x540 garden "textures with cutouts" --png out/garden.png
voxel_row glass 960x540 glass "physical lighting, 4 samples per pixel, bloom 0.3" \
  --bloom 0.3 --samples 4 --png out/glass.png
voxel_row cottage 960x540 cottage "a MagicaVoxel model (sample.vox): glass windows, glowing flowers" \
  --png out/cottage.png
voxel_row cottage 960x540 cottage-rc "global illumination: radiance cascades, sky and bounces" \
  --solver rc --png out/cottage-rc.png
voxel_row fence 480x270 fence "2-degree sun, MSM + SDF blend" --lighting physical \
  --png out/fence.png
voxel_row terrain 960x540 terrain-post "bloom 0.3, rendered at 480x270, edge-aware upscale" \
  --bloom 0.3 --internal-scale 0.5 --upscaler edge --png out/terrain-post.png
# Sparse voxel octrees: the terrain world as a DAG (surface, hard shadows), a CT-like phantom
# (translucent, scattering), and a 4096^3 terrain no dense grid could hold (soft shadows).
for name in world phantom terrain; do
  start=$(date +%s%N)
  "$luxel" render "scenes/octree/$name.json" --quiet --out "out/octree-$name.exr" \
    --png "out/octree-$name.png"
  osize=$("$luxel" info "scenes/octree/$name.json" | awk '/^  image/ {sub(",", "", $2); print $2; exit}')
  row "octree-$name" octree - "$osize" "$(ms_since "$start")" \
    "out/octree-$name.exr out/octree-$name.png"
done

echo
echo "hrc vs reference on $default_scene:"
"$luxel" compare "out/$default_scene-hrc.exr" "out/$default_scene.exr" \
  --diff "out/$default_scene-hrc-diff.png" | sed 's/^/  /'
echo "all 2D solvers on $default_scene, against out/$default_scene.exr:"
"$luxel" compare-solvers "scenes/2d/$default_scene.json" --reference "out/$default_scene.exr" \
  --grid "out/$default_scene-solvers.png" | sed 's/^/  /'

# Reference renders double as the benchmark's error yardstick (bench/bench_cascades2d.cpp).
mkdir -p out/reference-cache
cp "out/$default_scene.exr" "out/reference-cache/${default_scene}_$size.exr"

total_ms=$(ms_since "$total_start")
printf '\ntotal %d.%d s. What to open:\n' $((total_ms / 1000)) $((total_ms % 1000 / 100))
open_row() { printf '  %-26s %s\n' "$1" "$2"; }
open_row "out/$default_scene.png" "the default 2D scene, reference solver (ground truth)"
open_row "out/$default_scene-solvers.png" "reference, HRC, RC vanilla, RC bilinear fix side by side, labelled"
open_row "out/$default_scene-hrc-diff.png" "where HRC differs from the reference (white = largest error)"
open_row "out/penumbra.png ..." "the other 2D scenes: penumbra, pinhole, fog, thin-walls, many-lights"
open_row "out/terrain.png" "a voxel world: shadows, reflections, water (out/glass.png: refraction)"
open_row "out/cottage.png" "a MagicaVoxel .vox model with materials (luxel render any.vox works too)"
open_row "out/cottage-rc.png" "the same lit by voxel radiance cascades: sky light, glow and bounces"
open_row "out/octree-terrain.png" "a 4096^3 sparse voxel octree (out/octree-phantom.png: a volume)"
open_row "out/*.exr" "linear fluence and radiance, for measuring (luxel compare A.exr B.exr)"
echo "Every image says how it was made: luxel info out/$default_scene.png"
