#!/usr/bin/env bash
# Builds luxel without the GPU backend and the viewer (LUXEL_GPU=OFF, LUXEL_BUILD_VIEWER=OFF) and
# checks that this build needs none of Vulkan, glslc, SDL2 and Dear ImGui, and that it works:
#   - configure with glslc pointed at a file that does not exist, and no mention of Vulkan, SDL2
#     or ImGui in the configure output;
#   - build everything it builds (libraries, CLI, tests, fuzz smoke runs); no object includes a
#     Vulkan header;
#   - `luxel devices` and `--backend gpu` fail naming LUXEL_GPU=OFF, `--backend auto` falls back;
#   - a selection of tests (GPU tests skip), and the install-and-consume package test.
# Not part of `make test`: a second full build takes long. Usage: tools/check-cpu-only.sh [BUILD_DIR]
# (default build/cpu-only) with JOBS=N for the build's parallelism.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/cpu-only}
jobs=${JOBS:-$(nproc)}

fail() {
    echo "check-cpu-only: FAILED: $*" >&2
    exit 1
}

# --fresh: a new cache, so nothing found by an earlier configure of this directory counts.
log=$(cmake --fresh -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DLUXEL_WERROR=ON \
    -DLUXEL_GPU=OFF -DLUXEL_BUILD_VIEWER=OFF -DLUXEL_BUILD_BENCH=OFF \
    -DGLSLC_EXECUTABLE=/nonexistent/glslc 2>&1) || fail "configure: $log"
# CMake lists GLSLC_EXECUTABLE among the variables the project did not use; nothing else may
# name a GPU or viewer dependency.
grep -q '^ *GLSLC_EXECUTABLE$' <<<"$log" || fail "the configure step used GLSLC_EXECUTABLE: $log"
if grep -Ei 'vulkan|glslc|sdl2|imgui' <<<"$log" | grep -v '^ *GLSLC_EXECUTABLE$'; then
    fail "the configure step looked for a GPU or viewer dependency (lines above)"
fi
# (The glslc path given above is in the cache as an UNINITIALIZED entry: set, never used.)
if grep -Ei '^(vulkan|glslc|sdl2|imgui)[^:]*:' "$build/CMakeCache.txt" | grep -v ':UNINITIALIZED='
then
    fail "the cache holds GPU or viewer dependencies (lines above)"
fi
echo "check-cpu-only: configured without Vulkan, glslc, SDL2 or ImGui"

cmake --build "$build" -j "$jobs"
if ninja -C "$build" -t deps | grep '/vulkan/'; then
    fail "an object includes a Vulkan header (above)"
fi
echo "check-cpu-only: built; no object includes a Vulkan header"

cli="$build/apps/cli/luxel"
out=$("$cli" devices 2>&1) && fail "luxel devices succeeded: $out"
grep -q "LUXEL_GPU=OFF" <<<"$out" || fail "luxel devices: $out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scene=scenes/2d/penumbra.json
out=$("$cli" render "$scene" --solver hrc --size 64x64 --backend gpu --out "$tmp/g.exr" 2>&1) &&
    fail "--backend gpu succeeded: $out"
grep -q "LUXEL_GPU=OFF" <<<"$out" || fail "--backend gpu: $out"
out=$("$cli" render "$scene" --solver hrc --size 64x64 --out "$tmp/a.exr" 2>&1) ||
    fail "--backend auto: $out"
grep -q "using the CPU" <<<"$out" || fail "--backend auto gave no CPU note: $out"
echo "check-cpu-only: the CLI reports the missing backend and falls back to the CPU"

ctest --test-dir "$build" -j "$jobs" --output-on-failure \
    -R '^(Gpu|BackendPolicy|RcPasses|HrcPasses|PostGpu|OctreeTilesLayout|Hrc|Cli|FuzzSmoke|package)'
echo "check-cpu-only: passed"
