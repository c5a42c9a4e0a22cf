"""2D scenes and media: JSON in and out, rasterisation, numpy views of the medium, every solver."""
import os

import numpy as np
import pytest

import luxel


def test_scene_from_json_string_renders(sky_box):
    text = sky_box.to_json()
    scene = luxel.Scene2D.from_json(text)
    assert (scene.width, scene.height) == (64, 48)
    assert scene.shape_names == ["light", "wall"]
    fluence = luxel.render(scene, "reference", rays=256)
    assert fluence.shape == (48, 64, 3) and fluence.dtype == np.float32
    assert np.all(np.isfinite(fluence))
    # Inside the opaque light the fluence is its radiance (emission * intensity).
    assert fluence[24, 16] == pytest.approx([4.0, 3.6, 2.8], rel=0.01)
    # Behind the wall (right of it, level with the light) less light arrives than in front.
    assert fluence[24, 44].sum() < fluence[24, 28].sum()


def test_reference_and_hrc_agree(sky_box):
    reference = luxel.render(sky_box, "reference")
    hrc = luxel.render(sky_box, "hrc", backend="cpu")
    errors = luxel.compare(hrc, reference)
    # The bound tests/gi2d/hrc/hrc_solver_test.cpp uses for a sky and a rotated box.
    assert errors["rel_l1"] < 0.02, errors
    assert errors["counted_pixels"] == 64 * 48


def test_rc_merges_and_their_names(sky_box):
    reference = luxel.render(sky_box, "reference", rays=512)
    fix = luxel.render(sky_box, "rc", backend="cpu")
    vanilla = luxel.render(sky_box, "rc-vanilla", backend="cpu")
    same_vanilla = luxel.render(sky_box, "rc", merge="vanilla", backend="cpu")
    np.testing.assert_array_equal(vanilla, same_vanilla)
    assert not np.array_equal(fix, vanilla)
    # Both are approximations of the same fluence (docs/solver-errors.md): close, not equal.
    assert luxel.compare(fix, reference)["rel_l1"] < 0.15
    assert luxel.compare(vanilla, reference)["rel_l1"] < 0.25


def test_render_at_another_size(sky_box):
    small = luxel.render(sky_box, "hrc", width=32, height=24, backend="cpu")
    assert small.shape == (24, 32, 3)


def test_medium_views_share_memory_and_edits_reach_the_solver(sky_box):
    medium = sky_box.rasterize()
    assert (medium.width, medium.height) == (64, 48)
    emission = medium.emission
    assert emission.shape == (48, 64, 3) and emission.dtype == np.float32
    # Two reads view the same pixels: no copies.
    assert np.shares_memory(emission, medium.emission)
    assert emission.base is not None
    before = luxel.render(medium, "hrc", backend="cpu")
    medium.emission[:] = 0
    medium.boundary = (0, 0, 0)
    dark = luxel.render(medium, "hrc", backend="cpu")
    assert before.max() > 1.0
    assert np.abs(dark).max() < 1e-6


def test_medium_from_arrays_matches_the_rasterised_one(sky_box):
    rasterised = sky_box.rasterize()
    rebuilt = luxel.Medium.from_arrays(rasterised.emission, rasterised.absorption,
                                       boundary=rasterised.boundary)
    assert not np.shares_memory(rebuilt.emission, rasterised.emission)  # copied once
    a = luxel.render(rasterised, "hrc", backend="cpu")
    b = luxel.render(rebuilt, "hrc", backend="cpu")
    np.testing.assert_array_equal(a, b)


def test_uniform_emitter_reads_its_radiance():
    # A fully opaque canvas of radiance 2: every pixel sees only itself.
    emission = np.full((16, 20), 2.0, dtype=np.float64)  # grey, float64: converted once
    medium = luxel.Medium.from_arrays(emission, np.full((16, 20, 3), 64.0))
    fluence = luxel.render(medium, "reference", rays=64)
    np.testing.assert_allclose(fluence, 2.0, rtol=1e-4)


def test_bounce_light_brightens_a_scattering_fog():
    scene = luxel.Scene2D.from_json({
        "canvas": [40, 40],
        "background": {"absorption": 0.02, "albedo": 0.8},
        "shapes": [{"type": "circle", "center": [20, 20], "radius": 4, "emission": 1,
                    "opaque": True}],
    })
    assert scene.bounces
    medium = scene.rasterize()
    assert medium.bounces and medium.scattering.shape == (40, 40, 3)
    direct = luxel.render(scene, "hrc", bounces=0, backend="cpu")
    bounced = luxel.render(scene, "hrc", bounces=4, backend="cpu")
    far = (slice(0, 6), slice(0, 6))
    assert bounced[far].mean() > direct[far].mean() * 1.05


def test_display_image_is_tonemapped(sky_box):
    medium = sky_box.rasterize()
    fluence = luxel.render(medium, "hrc", backend="cpu")
    shown = luxel.display(medium, fluence, exposure=-1, curve="reinhard")
    assert shown.shape == (48, 64, 3)
    assert 0.0 <= shown.min() and shown.max() <= 1.0
    assert shown[24, 16].mean() > shown[24, 44].mean()


def test_load_shipped_scene(source_dir):
    scene = luxel.load_scene(str(source_dir / "scenes/2d/penumbra.json"))
    assert isinstance(scene, luxel.Scene2D)
    assert (scene.width, scene.height) == (512, 512)
    fluence = luxel.render(scene, "hrc", width=64, height=64, backend="cpu")
    assert fluence.shape == (64, 64, 3)
    # The light (left) is brighter than the shadow behind the occluder (right of it).
    assert fluence[32, 17].mean() > 10 * fluence[30, 45].mean()


def test_hrc_near_field_gathers_in_dense_fog_only(source_dir):
    fog = luxel.load_scene(os.path.join(source_dir, "scenes/2d/hard/dense-fog.json"))
    # The near field alone: at 64 px both lamps are compact lights, whose direct light is exact.
    args = dict(solver="hrc", width=64, height=64, backend="cpu", direct_light=False)
    gathered, plain = luxel.render(fog, **args), luxel.render(fog, near_field=False, **args)
    assert not np.array_equal(gathered, plain)
    room = luxel.load_scene(os.path.join(source_dir, "scenes/2d/room.json"))
    assert np.array_equal(luxel.render(room, **args), luxel.render(room, near_field=False, **args))
    with pytest.raises(luxel.Error, match="near_field applies to solver='hrc'"):
        luxel.render(room, solver="reference", near_field=False, width=16, height=16)


def test_hrc_direct_light_splits_compact_lights_only(source_dir):
    disk = luxel.load_scene(os.path.join(source_dir, "scenes/2d/hard/bright-disk.json"))
    args = dict(solver="hrc", width=64, height=64, backend="cpu")
    split, plain = luxel.render(disk, **args), luxel.render(disk, direct_light=False, **args)
    assert not np.array_equal(split, plain)
    room = luxel.load_scene(os.path.join(source_dir, "scenes/2d/room.json"))
    assert np.array_equal(luxel.render(room, **args), luxel.render(room, direct_light=False, **args))
    with pytest.raises(luxel.Error, match="direct_light applies to solver='hrc'"):
        luxel.render(room, solver="reference", direct_light=False, width=16, height=16)
