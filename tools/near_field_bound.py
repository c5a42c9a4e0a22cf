#!/usr/bin/env python3
"""How much of a 2D solver's error lies next to the lights: the solver's image with the pixels
within K px of an emitting pixel replaced by the reference's, against the reference, for several K
(docs/algorithms/holographic-radiance-cascades.md, section 12.3, "What an exact near field would
give"). An upper bound on what any correction confined to those pixels can gain.

Usage: tools/near_field_bound.py SCENE.json [--solver hrc] [--rays 2048] [--radii 0,1,2,3,4,6,8]
Needs the Python module built (build/release/python/module) and the CLI
(build/release/apps/cli/luxel); both images are rendered at the scene's canvas size.
"""
import argparse
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "build", "release", "python", "module"))
import luxel  # noqa: E402
import numpy as np  # noqa: E402


def distance_to_emitters(emitting, reach):
    """Per pixel, the distance in pixels to the nearest emitting pixel (inf beyond `reach`)."""
    h, w = emitting.shape
    out = np.full((h, w), np.inf)
    for dy in range(-reach, reach + 1):
        for dx in range(-reach, reach + 1):
            moved = np.zeros_like(emitting)
            y0, y1, x0, x1 = max(0, dy), min(h, h + dy), max(0, dx), min(w, w + dx)
            moved[y0:y1, x0:x1] = emitting[y0 - dy:y1 - dy, x0 - dx:x1 - dx]
            out = np.where(moved, np.minimum(out, np.hypot(dx, dy)), out)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene")
    parser.add_argument("--solver", default="hrc")
    parser.add_argument("--rays", type=int, default=2048)
    parser.add_argument("--radii", default="0,1,2,3,4,6,8")
    parser.add_argument("--luxel", default=os.path.join(ROOT, "build/release/apps/cli/luxel"))
    args = parser.parse_args()
    radii = [int(r) for r in args.radii.split(",")]
    with tempfile.TemporaryDirectory() as tmp:
        solver, reference = os.path.join(tmp, "solver.exr"), os.path.join(tmp, "reference.exr")
        subprocess.run([args.luxel, "render", args.scene, "--solver", args.solver, "--out", solver,
                        "-q"], check=True)
        subprocess.run([args.luxel, "render", args.scene, "--solver", "reference", "--rays",
                        str(args.rays), "--out", reference, "-q"], check=True)
        image, truth = luxel.read_image(solver), luxel.read_image(reference)
    emission = np.asarray(luxel.load_scene(args.scene).rasterize().emission)
    distance = distance_to_emitters(emission.max(axis=2) > 0.0, max(radii))
    mean = truth.mean()
    print(f"{args.scene}: {args.solver} against the reference ({args.rays} directions), "
          f"rel. L1 / RMSE of the mean")
    for k in [None] + radii:
        fixed = image.copy()
        if k is not None:
            near = distance <= k
            fixed[near] = truth[near]
        error = fixed - truth
        label = "as solved" if k is None else f"exact within {k} px ({int(near.sum())} px)"
        print(f"  {label:32s} {np.abs(error).mean() / mean * 100:6.2f}% "
              f"{np.sqrt((error ** 2).mean()) / mean * 100:6.2f}%")


if __name__ == "__main__":
    main()
