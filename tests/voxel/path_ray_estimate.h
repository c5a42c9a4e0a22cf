// The mean and standard error of the voxel path tracer along one ray (channel 0): the materials
// and sun-through-glass tests' analytic checks.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "luxel/voxel/path_trace.h"

namespace luxel::voxel::test {

struct Estimate {
    double mean = 0, standardError = 0;
};

// `n` path samples along `ray`, the world's emitters sampled as the tracer samples them.
inline Estimate traceRay(const VoxelWorld& world, const Ray& ray, const ShadeOptions& o,
                         const PathTraceOptions& p, int n, std::uint64_t pixel = 0) {
    const PathEmitters emitters = PathEmitters::find(world, o.materials);
    double sum = 0, squares = 0;
    for (int k = 0; k < n; ++k) {
        PathRng rng(p.seed, pixel, std::uint64_t(k));
        const double l = tracePath(world, nullptr, ray, o, p, rng, &emitters).r;
        sum += l, squares += l * l;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1))};
}

}  // namespace luxel::voxel::test
