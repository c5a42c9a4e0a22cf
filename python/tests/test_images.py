"""Images between luxel and numpy: shapes, values, which calls copy, and the file formats."""
import numpy as np
import pytest

import luxel


def test_rendered_image_owns_its_pixels_without_a_copy(sky_box):
    image = luxel.render(sky_box, "hrc", backend="cpu")
    assert image.flags["C_CONTIGUOUS"] and image.flags["WRITEABLE"]
    assert image.flags["OWNDATA"] is False  # the pixels belong to luxel's image...
    assert image.base is not None  # ...kept alive by the capsule the array holds
    assert type(image.base).__name__ == "PyCapsule"
    view = image[10:20]
    del image  # the view alone keeps the pixels alive
    assert np.all(np.isfinite(view))


def test_exr_round_trip_keeps_float_values(tmp_path):
    rng = np.random.default_rng(7)
    image = rng.uniform(0, 50, size=(13, 17, 3)).astype(np.float32)
    path = tmp_path / "x.exr"
    luxel.write_image(str(path), image)
    back = luxel.read_image(str(path))
    assert back.shape == (13, 17, 3) and back.dtype == np.float32
    np.testing.assert_array_equal(back, image)
    assert back.base is not None and not back.flags["OWNDATA"]  # handed over, not copied


def test_exr_round_trip_of_rgba_and_grey(tmp_path):
    rgba = np.linspace(0, 1, 5 * 4 * 4, dtype=np.float32).reshape(5, 4, 4)
    luxel.write_image(str(tmp_path / "a.exr"), rgba)
    np.testing.assert_array_equal(luxel.read_image(str(tmp_path / "a.exr")), rgba)
    grey = np.arange(12, dtype=np.float32).reshape(3, 4)
    luxel.write_image(str(tmp_path / "g.exr"), grey)
    back = luxel.read_image(str(tmp_path / "g.exr"))
    assert back.shape == (3, 4, 1)
    np.testing.assert_array_equal(back[..., 0], grey)


def test_png_round_trip_within_8_bit_steps(tmp_path):
    image = np.linspace(0, 1, 8 * 9 * 3, dtype=np.float32).reshape(8, 9, 3)
    path = tmp_path / "x.png"
    luxel.write_image(str(path), image)
    srgb = luxel.read_image(str(path))
    assert srgb.shape == (8, 9, 3)
    # sRGB-encoded 8 bits: one code step is at most ~1.3% of linear 1.0 near white.
    np.testing.assert_allclose(srgb, image, atol=0.014)
    luxel.write_image(str(path), image, encoding="linear")
    linear = luxel.read_image(str(path), encoding="linear")
    np.testing.assert_allclose(linear, image, atol=0.5 / 255 + 1e-6)


def test_any_numeric_input_is_accepted(tmp_path):
    # Non-contiguous float64: converted once on the way in.
    big = np.random.default_rng(1).uniform(0, 4, size=(10, 12, 3))
    strided = big[::2, ::3]
    out = luxel.tonemap(strided, exposure=0.0, curve="clamp")
    np.testing.assert_allclose(out, np.clip(strided, 0, 1), atol=1e-6)
    assert not np.shares_memory(out, big)
    ints = np.full((2, 2, 3), 3, dtype=np.int32)
    np.testing.assert_allclose(luxel.tonemap(ints, curve="reinhard"), 0.75, rtol=1e-6)


def test_tonemap_exposure_and_nan():
    hdr = np.array([[[1.0, 0.5, np.nan]]], dtype=np.float32)
    out = luxel.tonemap(hdr, exposure=-1.0, curve="clamp")
    np.testing.assert_allclose(out, [[[0.5, 0.25, 0.0]]])
    assert hdr[0, 0, 0] == 1.0  # the input is left alone


def test_compare_reports_known_errors():
    b = np.ones((4, 5, 3), dtype=np.float32)
    a = b.copy()
    a[0, 0, 0] = 3.0
    errors = luxel.compare(a, b)
    assert errors["max_abs"] == pytest.approx(2.0)
    assert errors["rel_l1"] == pytest.approx(2.0 / 60)
    assert errors["rmse"] == pytest.approx(np.sqrt(4.0 / 60))
    assert errors["mean_reference"] == pytest.approx(1.0)
    mask = np.ones((4, 5), dtype=np.float32)
    mask[0, 0] = 0
    masked = luxel.compare(a, b, mask=mask)
    assert masked["max_abs"] == 0 and masked["counted_pixels"] == 19


def test_writes_replace_the_target_only_when_complete(tmp_path):
    path = tmp_path / "keep.exr"
    good = np.ones((2, 2, 3), dtype=np.float32)
    luxel.write_image(str(path), good)
    with pytest.raises(luxel.Error, match="channels"):
        luxel.write_image(str(path), np.ones((2, 2, 5), dtype=np.float32))
    np.testing.assert_array_equal(luxel.read_image(str(path)), good)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["keep.exr"]
