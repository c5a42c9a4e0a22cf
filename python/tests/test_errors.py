"""Errors reach Python as luxel.Error with luxel's located messages."""
import json

import numpy as np
import pytest

import luxel


def test_error_is_a_runtime_error():
    assert issubclass(luxel.Error, RuntimeError)


def test_bad_json_names_line_and_column():
    text = '{\n  "canvas": [64, 48],\n  "shapes": [ {"type": "circle",, } ]\n}'
    with pytest.raises(luxel.Error, match=r"^bad\.json:3:\d+: ") as info:
        luxel.Scene2D.from_json(text, name="bad.json")
    assert "\n" not in str(info.value)


def test_bad_field_names_location_and_field(tmp_path):
    scene = {"canvas": [64, 48],
             "shapes": [{"type": "circle", "center": [5, 5], "radius": -4, "emission": 1}]}
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene, indent=2))
    with pytest.raises(luxel.Error) as info:
        luxel.load_scene(str(path))
    message = str(info.value)
    assert message.startswith(str(path) + ":"), message
    assert "shapes[0].radius" in message and "-4" in message
    line, column = message[len(str(path)) + 1:].split(":")[:2]
    assert int(line) > 1 and int(column) > 0


def test_missing_file_is_named(tmp_path):
    missing = tmp_path / "nope.json"
    with pytest.raises(luxel.Error, match="nope.json"):
        luxel.load_scene(str(missing))
    with pytest.raises(luxel.Error, match="nope.exr"):
        luxel.read_image(str(tmp_path / "nope.exr"))


def test_unknown_choices_list_the_valid_ones(sky_box):
    with pytest.raises(luxel.Error, match="solver.*reference.*hrc.*rc"):
        luxel.render(sky_box, "path-tracer")
    with pytest.raises(luxel.Error, match="backend.*auto.*cpu.*gpu"):
        luxel.render(sky_box, "hrc", backend="tpu")
    with pytest.raises(luxel.Error, match="rays applies to solver='reference', not 'hrc'"):
        luxel.render(sky_box, "hrc", rays=64)
    with pytest.raises(luxel.Error, match="reference solver runs on the CPU only"):
        luxel.render(sky_box, "reference", backend="gpu")
    with pytest.raises(luxel.Error, match="rays must be in 1.."):
        luxel.render(sky_box, "reference", rays=0)
    with pytest.raises(luxel.Error, match="curve 'filmic' is not clamp, reinhard or aces"):
        luxel.tonemap(np.zeros((2, 2, 3)), curve="filmic")


def test_bad_sizes(sky_box):
    with pytest.raises(luxel.Error, match="0x10"):
        sky_box.rasterize(width=0, height=10)
    with pytest.raises(luxel.Error, match="both width and height"):
        sky_box.rasterize(width=10)


def test_wrong_array_shapes_and_types():
    with pytest.raises(luxel.Error, match=r"image: shape \(5,\) is not \(height, width\)"):
        luxel.tonemap(np.zeros(5))
    with pytest.raises(luxel.Error, match="6 channels; 1 to 4"):
        luxel.tonemap(np.zeros((2, 2, 6)))
    with pytest.raises(luxel.Error, match="dtype <U1 is not a number type|dtype.*not a number"):
        luxel.tonemap(np.array([["a", "b"]]))
    with pytest.raises(luxel.Error, match="sizes|size"):
        luxel.compare(np.zeros((2, 2, 3)), np.zeros((2, 3, 3)))
    with pytest.raises(luxel.Error, match="emission: has 2 channels"):
        luxel.Medium.from_arrays(np.zeros((4, 4, 2)), np.zeros((4, 4, 3)))
    with pytest.raises(luxel.Error, match=r"medium.absorption: 5x4x3, expected 4x4x3"):
        luxel.Medium.from_arrays(np.zeros((4, 4, 3)), np.zeros((4, 5, 3)))


def test_nan_and_out_of_range_values_are_refused_with_the_pixel():
    emission = np.zeros((4, 6, 3), dtype=np.float32)
    absorption = np.zeros((4, 6, 3), dtype=np.float32)
    absorption[2, 5, 1] = np.nan
    with pytest.raises(luxel.Error,
                       match=r"medium\.absorption\[y=2, x=5, channel 1\]: must be finite, got nan"):
        luxel.Medium.from_arrays(emission, absorption)
    absorption[2, 5, 1] = 0
    emission[1, 3, 0] = -1
    with pytest.raises(luxel.Error, match=r"medium\.emission\[y=1, x=3, channel 0\]: must be in"):
        luxel.Medium.from_arrays(emission, absorption)
    emission[1, 3, 0] = 0
    with pytest.raises(luxel.Error, match=r"boundary: expected three finite values"):
        luxel.Medium.from_arrays(emission, absorption, boundary=(0, float("inf"), 0))
    # Edits through the writable views are checked before the next solve.
    medium = luxel.Medium.from_arrays(emission, absorption)
    medium.emission[0, 0, 2] = np.inf
    with pytest.raises(luxel.Error, match=r"medium\.emission\[y=0, x=0, channel 2\]: must be finite"):
        luxel.render(medium, "hrc", backend="cpu")
    with pytest.raises(luxel.Error, match="must be finite"):
        medium.validate()


def test_octree_scenes_say_what_to_use(source_dir):
    with pytest.raises(luxel.Error, match="octree scene.*luxel render"):
        luxel.load_scene(str(source_dir / "scenes/octree/phantom.json"))
