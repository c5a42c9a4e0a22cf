"""Voxel worlds from numpy arrays, cameras, voxel scenes and their renders."""
import numpy as np
import pytest

import luxel


def test_world_round_trips_through_numpy(red_block_world):
    rng = np.random.default_rng(3)
    voxels = rng.integers(0, 256, size=(9, 7, 11, 4), dtype=np.uint8)
    voxels[rng.random((9, 7, 11)) < 0.5] = 0  # half empty
    voxels[0, 0, 0] = (10, 20, 30, 0)  # an empty voxel with a colour survives too
    world = luxel.VoxelWorld.from_array(voxels, chunk_size=4)
    assert world.shape == (9, 7, 11) and world.chunk_size == 4
    assert world.solid_count == int(np.count_nonzero(voxels[..., 3]))
    back = world.to_array()
    assert back.shape == voxels.shape and back.dtype == np.uint8
    np.testing.assert_array_equal(back, voxels)
    assert world[3, 2, 1] == tuple(int(c) for c in voxels[3, 2, 1])
    # Strided input is accepted too (copied once into the chunked layout).
    flipped = luxel.VoxelWorld.from_array(voxels[::-1])
    np.testing.assert_array_equal(flipped.to_array(), voxels[::-1])
    assert flipped != world


def test_render_sees_the_block_colour_at_the_centre(red_block_world):
    world = luxel.VoxelWorld.from_array(red_block_world)
    camera = luxel.Camera.look_at((8, 8, -12), (8, 8, 8), fov=40, width=32, height=24)
    image = luxel.render_voxel(world, camera, backend="cpu", reflections=0)
    assert image.shape == (24, 32, 3) and image.dtype == np.float32
    # The block's colour, sRGB (220, 30, 20) -> linear (0.72, 0.012, 0.007), times the face
    # shading: red, with almost no green or blue.
    r, g, b = image[12, 16]
    assert r > 0.1 and r > 20 * g and r > 20 * b, (r, g, b)
    # The corners miss the block and see the sky, which is bluest.
    corner = image[0, 0]
    assert corner[2] > corner[1] > corner[0] > 0.1
    # Default shading mixes in the sky's reflection, but red still leads.
    reflecting = luxel.render_voxel(world, camera, backend="cpu")[12, 16]
    assert reflecting[0] > reflecting[1] and reflecting[0] > reflecting[2]
    assert reflecting[1] > g  # the sky's reflection adds green


def test_world_edits_show_in_the_next_render(red_block_world):
    world = luxel.VoxelWorld.from_array(red_block_world)
    camera = luxel.Camera((8, 8, -12), yaw=0, pitch=0, fov=40, width=16, height=16)
    before = luxel.render_voxel(world, camera, backend="cpu")
    # A green wall in front of the block, facing the camera.
    for x in range(4, 13):
        for y in range(4, 13):
            world[x, y, 2] = (20, 200, 30, 255)
    after = luxel.render_voxel(world, camera, backend="cpu")
    assert before[8, 8, 0] > before[8, 8, 1]
    assert after[8, 8, 1] > after[8, 8, 0]


def test_voxel_scene_from_world_and_from_json(red_block_world):
    world = luxel.VoxelWorld.from_array(red_block_world)
    camera = luxel.Camera.look_at((8, 8, -12), (8, 8, 8), width=16, height=16)
    scene = luxel.VoxelScene(world, camera)
    scene.world[8, 8, 5] = (0, 0, 0, 0)  # edits the scene's own copy of the world
    assert world[8, 8, 5] == (220, 30, 20, 255)
    assert scene.world[8, 8, 5] == (0, 0, 0, 0)
    assert scene.world.solid_count == world.solid_count - 1
    image = luxel.render(scene, backend="cpu")
    assert image.shape == (16, 16, 3)
    with pytest.raises(luxel.Error, match="solver applies to 2D scenes"):
        luxel.render(scene, "hrc")


def test_shipped_voxel_scene_renders_small(source_dir):
    scene = luxel.load_scene(str(source_dir / "scenes/voxel/terrain-direct.json"),
                             width=24, height=16)
    assert isinstance(scene, luxel.VoxelScene)
    assert (scene.camera.width, scene.camera.height) == (24, 16)
    image = luxel.render_voxel(scene, backend="cpu")
    assert image.shape == (16, 24, 3)
    assert np.all(np.isfinite(image)) and image.max() > 0.05
    assert scene.curve in ("clamp", "reinhard", "aces")
    shown = luxel.tonemap(image, exposure=scene.exposure, curve=scene.curve)
    assert 0 <= shown.min() and shown.max() <= 1


def test_world_from_array_refuses_bad_arrays():
    with pytest.raises(luxel.Error, match=r"shape \(4, 4, 4\) is not \(nx, ny, nz, 4\)"):
        luxel.VoxelWorld.from_array(np.zeros((4, 4, 4), dtype=np.uint8))
    with pytest.raises(luxel.Error, match=r"shape \(4, 4, 4, 3\)"):
        luxel.VoxelWorld.from_array(np.zeros((4, 4, 4, 3), dtype=np.uint8))
    with pytest.raises(luxel.Error, match="dtype float32 is not uint8"):
        luxel.VoxelWorld.from_array(np.zeros((4, 4, 4, 4), dtype=np.float32))
    with pytest.raises(luxel.Error, match="each side must be in 1..4096"):
        luxel.VoxelWorld.from_array(np.zeros((0, 4, 4, 4), dtype=np.uint8))
    world = luxel.VoxelWorld(4, 4, 4)
    with pytest.raises(IndexError):
        world[4, 0, 0] = (1, 2, 3, 255)
    with pytest.raises(luxel.Error, match="each 0..255"):
        world[0, 0, 0] = (1, 2, 300, 255)


def test_camera_refuses_bad_values():
    with pytest.raises(luxel.Error, match="pitch"):
        luxel.Camera((0, 0, 0), pitch=95)
    with pytest.raises(luxel.Error, match="position: expected three finite numbers"):
        luxel.Camera((0, float("nan"), 0))
