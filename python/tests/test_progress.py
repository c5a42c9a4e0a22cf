"""Progress callbacks during solves, and what an exception raised in one does."""
import threading
import time

import pytest

import luxel


def test_reference_reports_increasing_fractions(sky_box):
    seen = []
    luxel.render(sky_box, "reference", rays=64, progress=seen.append)
    assert len(seen) >= 10  # 48 rows, reported at least every few rows
    assert all(b > a for a, b in zip(seen, seen[1:])), seen
    assert 0 < seen[0] < 1 and seen[-1] == 1.0


def test_hrc_reports_each_frustum(sky_box):
    seen = []
    luxel.render(sky_box, "hrc", backend="cpu", progress=seen.append)
    assert seen == [0.25, 0.5, 0.75, 1.0]


def test_rc_and_voxel_renders_report_the_end(sky_box, red_block_world):
    seen = []
    luxel.render(sky_box, "rc", backend="cpu", progress=seen.append)
    assert seen == [1.0]
    seen.clear()
    world = luxel.VoxelWorld.from_array(red_block_world)
    camera = luxel.Camera((8, 8, -12), width=8, height=8)
    luxel.render_voxel(world, camera, backend="cpu", progress=seen.append)
    assert seen == [1.0]


def test_bounces_report_across_all_solves():
    scene = luxel.Scene2D.from_json({
        "canvas": [24, 24], "background": {"absorption": 0.05, "albedo": 0.5},
        "shapes": [{"type": "circle", "center": [12, 12], "radius": 3, "emission": 1,
                    "opaque": True}]})
    seen = []
    luxel.render(scene, "hrc", bounces=3, backend="cpu", progress=seen.append)
    # 4 solves of 4 frustums each.
    assert len(seen) == 16 and seen[-1] == 1.0
    assert all(b > a for a, b in zip(seen, seen[1:]))


class Stop(Exception):
    pass


def test_exception_in_callback_cancels_and_propagates(sky_box):
    calls = []

    def stop_early(fraction):
        calls.append(fraction)
        raise Stop(f"stopped at {fraction:.2f}")

    with pytest.raises(Stop, match="stopped at"):
        luxel.render(sky_box, "reference", rays=4096, progress=stop_early)
    assert len(calls) == 1  # no further calls once it raised
    with pytest.raises(Stop):
        luxel.render(sky_box, "hrc", backend="cpu", progress=stop_early)
    assert len(calls) == 2
    # The module is still usable afterwards.
    assert luxel.render(sky_box, "hrc", backend="cpu").shape == (48, 64, 3)


def test_cancel_stops_a_long_solve_early(sky_box):
    # 256 narrow rows of 64k rays per pixel take a minute on two cores; a cancel ends the solve
    # once the rows in flight (one per thread) are done.
    stopped = []

    def stop(_):
        stopped.append(time.monotonic())
        raise KeyboardInterrupt

    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        luxel.render(sky_box, "reference", rays=65536, width=8, height=256, progress=stop)
    end = time.monotonic()
    first_rows = stopped[0] - start  # at least one row per thread
    assert end - stopped[0] < 4 * first_rows + 0.5, (first_rows, end - stopped[0])


def test_progress_must_be_callable(sky_box):
    with pytest.raises(TypeError, match="progress must be callable"):
        luxel.render(sky_box, "hrc", backend="cpu", progress=3)


def test_solves_release_the_gil(sky_box):
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.002)

    thread = threading.Thread(target=tick)
    thread.start()
    try:
        luxel.render(sky_box, "reference", rays=1024)
    finally:
        done.set()
        thread.join()
    assert len(ticks) >= 5  # the other thread ran while the solve did
