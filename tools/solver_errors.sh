#!/bin/sh
# Renders the error images and numbers of docs/solver-errors.md: every 2D solver against the
# reference on each scene of scenes/2d/hard, and each solver's change when a light moves.
# Usage: tools/solver_errors.sh [path/to/luxel]   (default build/release/apps/cli/luxel)
set -eu
luxel=${1:-build/release/apps/cli/luxel}
out=docs/images
for scene in scenes/2d/hard/*.json; do
    name=$(basename "$scene" .json)
    "$luxel" compare-solvers "$scene" --rays 512 --error-scale 10 \
        --error-image "$out/solver-errors-$name.png"
    echo
done
# One of 24 small lights moved by half a pixel (the brightest; 512x512, about 3 minutes).
"$luxel" compare-solvers scenes/2d/many-lights.json --rays 512 --move 0.5,0 --error-scale 2 \
    --error-image "$out/solver-errors-moving-light.png"
