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
for move in 0.5,0 1,0; do
    "$luxel" compare-solvers scenes/2d/hard/bright-disk.json --rays 512 --move "$move" \
        --error-scale 2 --error-image "$out/solver-errors-moving-light-$(echo "$move" | tr , _).png"
    echo
done
