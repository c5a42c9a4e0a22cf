"""The module itself: its version, and a docstring on everything it offers."""
import re

import luxel
from conftest import SOURCE_DIR


def test_version_is_the_project_version():
    cmake = (SOURCE_DIR / "CMakeLists.txt").read_text()
    version = re.search(r"project\(luxel VERSION ([0-9.]+)", cmake).group(1)
    assert luxel.__version__ == version


def test_everything_public_is_documented():
    names = [n for n in dir(luxel) if not n.startswith("_")]
    expected = {"Camera", "Error", "Medium", "Scene2D", "VoxelScene", "VoxelWorld", "compare",
                "devices", "display", "load_scene", "read_image", "render", "render_voxel",
                "tonemap", "write_image"}
    assert expected <= set(names)
    for name in names:
        doc = getattr(luxel, name).__doc__
        assert doc and len(doc) > 20, name
    assert "solver" in luxel.render.__doc__ and "progress" in luxel.render.__doc__
