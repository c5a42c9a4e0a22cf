#!/bin/sh
# Renders the error images and numbers of docs/solver-errors.md: every 2D solver against the
# reference on each scene of scenes/2d/hard, and each solver's change when a light moves.
# Usage: tools/solver_errors.sh [path/to/luxel]   (default build/release/apps/cli/luxel)
# Environment: RAYS, reference directions per pixel for the hard scenes (default 8192: about 40
# minutes on 2 cores, 3 on 16); OUTDIR (default docs/images); PARTS, "hard", "moving" or both
# (default).
set -eu
luxel=${1:-build/release/apps/cli/luxel}
out=${OUTDIR:-docs/images}
rays=${RAYS:-8192}
parts=${PARTS:-hard moving}
case " $parts " in *" hard "*)
    for scene in scenes/2d/hard/*.json; do
        name=$(basename "$scene" .json)
        "$luxel" compare-solvers "$scene" --rays "$rays" --error-scale 10 \
            --error-image "$out/solver-errors-$name.png"
        echo
    done ;;
esac
case " $parts " in *" moving "*)
    # One of 24 small lights moved by half a pixel (the brightest; 512x512, about 3 minutes): both
    # references use the same directions, so 512 rays leave little noise in the change.
    "$luxel" compare-solvers scenes/2d/many-lights.json --rays 512 --move 0.5,0 --error-scale 2 \
        --error-image "$out/solver-errors-moving-light.png" ;;
esac
