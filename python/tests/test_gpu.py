"""The GPU backend: it works (lavapipe counts) or says clearly why not. Small canvases, since a
software Vulkan device is slow."""
import numpy as np
import pytest

import luxel


def gpu_or_reason():
    try:
        return luxel.devices(), None
    except luxel.Error as error:
        return [], str(error)


def test_devices_are_listed_or_the_reason_given():
    devices, reason = gpu_or_reason()
    if reason is not None:
        assert reason  # a message, e.g. no Vulkan loader
        return
    for d in devices:
        assert set(d) >= {"index", "name", "type", "memory_bytes", "api_version", "used_by_auto"}
        assert isinstance(d["name"], str) and d["name"]


@pytest.mark.parametrize("solver", ["hrc", "rc"])
def test_gpu_backend_matches_cpu_or_raises(sky_box, solver):
    cpu = luxel.render(sky_box, solver, backend="cpu")
    try:
        gpu = luxel.render(sky_box, solver, backend="gpu")
    except luxel.Error as error:
        message = str(error)
        assert message.startswith("backend='gpu': ") and len(message) > len("backend='gpu': ")
        return
    assert gpu.shape == cpu.shape
    assert luxel.compare(gpu, cpu)["rel_l1"] < 1e-3


def test_gpu_voxel_render_matches_cpu_or_raises(red_block_world):
    world = luxel.VoxelWorld.from_array(red_block_world)
    camera = luxel.Camera.look_at((8, 8, -12), (8, 8, 8), fov=40, width=16, height=12)
    cpu = luxel.render_voxel(world, camera, backend="cpu")
    try:
        gpu = luxel.render_voxel(world, camera, backend="gpu")
    except luxel.Error as error:
        assert str(error).startswith("backend='gpu': ")
        return
    assert gpu.shape == cpu.shape
    # Float on the GPU vs double on the CPU: equal but for rare edge pixels.
    close = np.isclose(gpu, cpu, atol=1e-3).all(axis=2)
    assert close.mean() > 0.97


def test_auto_backend_always_renders(sky_box):
    assert luxel.render(sky_box, "hrc", backend="auto").shape == (48, 64, 3)
