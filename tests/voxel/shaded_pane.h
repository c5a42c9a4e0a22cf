// The top face of paneOverAFloor's pane shaded by shadeSolverSurface, seen from above: the tests
// of the solver's surface rules (air exits, sharp lobes) set the material and the light along
// each ray, and read the radiance and the rays whose light was asked for.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "luxel/voxel/surface_cast.h"
#include "voxel/plain_light_worlds.h"
#include "voxel/solver_surface.h"

namespace luxel::voxel::test {

struct ShadedPane {
    Rgb radiance;
    std::vector<Ray> rays;  // the rays whose light was asked for, in order
};

// `direction`: the camera's unit direction, downwards onto the pane; `lightAlong`: the radiance
// arriving along each ray leaving the face; `configure` sets the SolverLight's switches.
inline ShadedPane shadePaneTop(const ShadeOptions& options, Vec3d direction, int specularRays,
                               const std::function<Rgb(const Ray&)>& lightAlong,
                               const std::function<void(SolverLight&)>& configure, PathRng rng) {
    const VoxelWorld world = paneOverAFloor();
    const Ray camera{Vec3d{12.0, 7.5, 12.0} - direction * 1.0, direction};
    const SurfaceHit s = castToSurface(world, nullptr, camera, options.stepCap);
    EXPECT_TRUE(s.hit.hit);
    EXPECT_EQ(s.hit.normal, (Int3{0, 1, 0}));
    ShadedPane out;
    SolverLight light{Rgb(0.0f),
                      [&out, &lightAlong](const Ray& r, bool) {
                          out.rays.push_back(r);
                          return lightAlong(r);
                      },
                      1, specularRays};
    configure(light);
    out.radiance = shadeSolverSurface(world, nullptr, s, camera, options, light, rng);
    return out;
}

// No light but what the test hands the pane's rays, the pane a metal of `roughness` (texture slot
// 0 of paneOverAFloor's pane).
inline ShadeOptions metalPaneOptions(float roughness) {
    ShadeOptions o = plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    EXPECT_TRUE(o.materials.setSlot(0, metal(roughness, Rgb(0.9f, 0.8f, 0.7f))).ok());
    return o;
}

// Light along a ray that depends on its direction, differently in each channel: a surface's
// rays bring different light, so which rays were taken shows in the radiance.
inline Rgb lightVaryingWithDirection(const Ray& r) {
    return Rgb(float(1.0 + 3.0 * r.direction.x), 1.0f, float(1.0 + 5.0 * r.direction.z));
}

// The same radiance to the bit, channel by channel.
inline void expectSameRgb(const Rgb& a, const Rgb& b) {
    EXPECT_EQ(a.r, b.r);
    EXPECT_EQ(a.g, b.g);
    EXPECT_EQ(a.b, b.b);
}

}  // namespace luxel::voxel::test
