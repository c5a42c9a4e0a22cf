// The volume mode's scattering (octree_render.h, the subsurface scattering of translucent
// matter) against brute-force Monte Carlo volume path tracing (octree_path_trace.h) on a small
// sphere of participating medium lit by the sun from the side.
#include <gtest/gtest.h>

#include <cmath>

#include "luxel/core/metrics.h"
#include "luxel/octree/octree_build.h"
#include "luxel/octree/octree_path_trace.h"
#include "luxel/octree/octree_render.h"

namespace luxel::octree {
namespace {

Octree mediumSphere() {
    Volume v = *Volume::create({24, 24, 24});
    for (int z = 0; z < 24; ++z)
        for (int y = 0; y < 24; ++y)
            for (int x = 0; x < 24; ++x) {
                const double dx = x + 0.5 - 12, dy = y + 0.5 - 12, dz = z + 0.5 - 12;
                if (dx * dx + dy * dy + dz * dz < 81) v.set(x, y, z, 255);
            }
    return *buildOctree(v);
}

double relativeL1(const Image& a, const Image& b) {
    return compareImages(a, b)->relativeL1;
}

struct Scene {
    Octree tree = mediumSphere();
    voxel::Camera camera = *voxel::Camera::lookAt({12, 14, -30}, {12, 12, 12}, 40, 32, 32);
    OctreeRenderOptions medium = [] {
        OctreeRenderOptions o;
        o.mode = OctreeMode::Volume;
        o.opacityScale = 0.35f;  // sigma_t = 0.43 per voxel: optical diameter about 8
        o.albedo = 0.9f;
        o.phaseG = 0.3f;
        o.sunDirection = {0.8f, 0.5f, -0.3f};
        o.sky = {0, 0, 0};
        o.ambient = 0;
        return o;
    }();
};

TEST(OctreeScattering, SingleScatteringMatchesMonteCarloWithOneBounce) {
    Scene s;
    s.medium.octaves = 1;
    auto approx = renderOctree(s.tree, s.camera, s.medium);
    auto truth =
        pathTraceOctree(s.tree, s.camera, s.medium, {.samplesPerPixel = 512, .maxScatterings = 1});
    ASSERT_TRUE(approx.ok() && truth.ok());
    const double error = relativeL1(*approx, *truth);
    EXPECT_LT(error, 0.03) << "single scattering vs one-bounce Monte Carlo";
}

// The octave defaults (3 octaves, weight ratio 0.3) were chosen on this scene (measured: single
// scattering 0.43 from the truth, the octaves 0.09) ...
TEST(OctreeScattering, MultipleScatteringOctavesApproachTheFullSolution) {
    Scene s;
    auto truth =
        pathTraceOctree(s.tree, s.camera, s.medium, {.samplesPerPixel = 512, .maxScatterings = 64});
    ASSERT_TRUE(truth.ok());
    s.medium.octaves = 1;
    const double singleError = relativeL1(*renderOctree(s.tree, s.camera, s.medium), *truth);
    s.medium.octaves = OctreeRenderOptions{}.octaves;
    const double octaveError = relativeL1(*renderOctree(s.tree, s.camera, s.medium), *truth);
    EXPECT_GT(singleError, 0.35);  // single scattering alone loses much of the light here
    EXPECT_LT(octaveError, 0.12);
}

// ... and checked on another: a denser, darker, more forward-scattering box lit from above and
// behind, seen from another side (measured: single scattering 0.38, the octaves 0.17).
TEST(OctreeScattering, TheOctaveDefaultsHoldOnAnotherMediumAndLight) {
    Volume v = *Volume::create({24, 24, 24});
    for (int z = 4; z < 20; ++z)
        for (int y = 2; y < 16; ++y)
            for (int x = 6; x < 22; ++x) v.set(x, y, z, 200);
    const Octree tree = *buildOctree(v);
    const voxel::Camera camera = *voxel::Camera::lookAt({-20, 20, -16}, {14, 9, 12}, 45, 32, 32);
    OctreeRenderOptions medium;
    medium.mode = OctreeMode::Volume;
    medium.opacityScale = 0.6f;
    medium.albedo = 0.75f;
    medium.phaseG = 0.5f;
    medium.sunDirection = {0.2f, 1.0f, 0.6f};
    medium.sky = {0, 0, 0};
    medium.ambient = 0;
    auto truth =
        pathTraceOctree(tree, camera, medium, {.samplesPerPixel = 512, .maxScatterings = 64});
    ASSERT_TRUE(truth.ok());
    medium.octaves = 1;
    const double singleError = relativeL1(*renderOctree(tree, camera, medium), *truth);
    medium.octaves = OctreeRenderOptions{}.octaves;
    const double octaveError = relativeL1(*renderOctree(tree, camera, medium), *truth);
    EXPECT_LT(octaveError, singleError);
    EXPECT_LT(octaveError, 0.2);
}

}  // namespace
}  // namespace luxel::octree
