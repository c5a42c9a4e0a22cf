"""Shared fixtures for the luxel Python tests (run by ctest with PYTHONPATH at the built module)."""
import os
import pathlib

import numpy as np
import pytest

import luxel

SOURCE_DIR = pathlib.Path(
    os.environ.get("LUXEL_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))

# A light, a box between it and the right side, a faint sky: small enough for the reference
# solver to run in well under a second.
SKY_BOX = {
    "canvas": [64, 48],
    "background": {"emission": 0, "absorption": 0.004},
    "boundary_radiance": [0.5, 0.6, 0.8],
    "shapes": [
        {"type": "circle", "name": "light", "center": [16, 24], "radius": 5,
         "emission": [1.0, 0.9, 0.7], "intensity": 4, "opaque": True},
        {"type": "box", "name": "wall", "center": [36, 24], "size": [4, 24], "angle": 20,
         "emission": 0, "opaque": True},
    ],
}


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture
def sky_box():
    return luxel.Scene2D.from_json(SKY_BOX, name="sky-box.json")


@pytest.fixture
def red_block_world():
    """A 16^3 world: a 6^3 red block in the middle (voxels 5..10 on each axis)."""
    voxels = np.zeros((16, 16, 16, 4), dtype=np.uint8)
    voxels[5:11, 5:11, 5:11] = (220, 30, 20, 255)
    return voxels
