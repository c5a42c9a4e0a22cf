// The 2D solvers from Python: luxel.render on a Scene2D or a Medium (solvers.cpp), and the
// voxel path it hands voxel scenes to (voxel_render.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "bindings.h"

namespace luxel::python {

// Arguments of luxel.render that only 2D scenes take; unset ones use the solver's defaults.
struct Solve2DArgs {
    std::optional<std::string> solver;  // "reference" (default), "hrc", "rc", "rc-vanilla"
    std::optional<int> width, height, supersample;
    std::optional<int> rays;
    std::optional<std::uint64_t> seed;
    std::optional<int> bounces;
    std::optional<int> tracedLevels;
    std::optional<bool> crossBlur;
    std::optional<bool> nearField;  // HRC's exact near field where the medium bounds the rays
    std::optional<std::string> merge;
    std::optional<int> probeSpacing, baseRays, maxCascades, jitters;
    std::optional<double> baseInterval;
    std::optional<bool> directLight;  // HRC's exact direct light from compact lights (§12.5)

    // The first option given, by its Python name ("" when none): voxel scenes refuse them.
    std::string firstGiven() const;
};

// Arguments every render takes.
struct RenderCommon {
    std::string backend = "auto";
    std::string device;
    int threads = 0;
    py::object progress = py::none();
};

// Caps TBB's worker threads while alive (0: all cores); refuses counts outside 0..4096.
void checkThreads(int threads);

// luxel.render_voxel on a VoxelScene (voxel_render.cpp), for luxel.render.
py::object renderVoxelScene(py::handle scene, const RenderCommon& common);

}  // namespace luxel::python
