// GgxTowards (src/voxel/path_trace_bsdf.h): one direction's GGX density and delta light, the half
// vector and D found once for both, are ggxDensity's and bsdfLight's (lightPdf 0) to the bit,
// over every face normal, many views, directions and roughnesses, for the specular-only lobe
// the glossy lamps' light samples use and for a lobe with a diffuse part; directions below the
// face and half vectors below it included.
#include <gtest/gtest.h>

#include <cmath>

#include "luxel/voxel/path_trace_rng.h"
#include "voxel/path_trace_bsdf.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

Vec3d randomUnit(PathRng& rng) {
    for (;;) {
        const Vec3d v{2.0 * rng.next() - 1.0, 2.0 * rng.next() - 1.0, 2.0 * rng.next() - 1.0};
        const double l2 = dot(v, v);
        if (l2 > 1e-4 && l2 <= 1.0) return v * (1.0 / std::sqrt(l2));
    }
}

TEST(GgxTowards, IsGgxDensityAndBsdfLightToTheBit) {
    const Int3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    PathRng rng(5, 0, 0);
    int lit = 0, dark = 0, checked = 0;
    for (const Int3 n : normals) {
        const Vec3d nd{double(n.x), double(n.y), double(n.z)};
        for (const float roughness : {0.05f, 0.3f, 0.7f, 1.0f}) {
            for (const bool diffuse : {false, true}) {
                for (int v = 0; v < 24; ++v) {
                    Vec3d view = randomUnit(rng);
                    if (dot(view, nd) < 0.0) view = view - nd * (2.0 * dot(view, nd));
                    PathBsdf b;
                    b.normal = n;
                    b.view = view;
                    b.cosView = dot(nd, view);
                    b.alpha = roughness * roughness;
                    b.specular = Rgb(0.04f, 0.05f, 0.06f);
                    b.pSpecular = diffuse ? 0.2 : 1.0;
                    if (diffuse) {
                        b.diffuse = Rgb(0.5f, 0.4f, 0.3f);
                        b.pDiffuse = 0.8;
                    }
                    for (int k = 0; k < 8; ++k) {
                        const Vec3d l = randomUnit(rng);  // half of them below the face
                        const Rgb radiance(3.0f, 2.0f, 1.0f);
                        const GgxTowards towards(b, l);
                        const double density = ggxDensity(b, l);
                        const Rgb light = bsdfLight(b, l, radiance, 0.0);
                        const Rgb fused = towards.deltaLight(radiance);
                        ASSERT_EQ(towards.density(), density);
                        ASSERT_EQ(fused.r, light.r);
                        ASSERT_EQ(fused.g, light.g);
                        ASSERT_EQ(fused.b, light.b);
                        (light.maxComponent() > 0.0f ? lit : dark) += 1;
                        ++checked;
                    }
                }
            }
        }
    }
    EXPECT_EQ(checked, 6 * 4 * 2 * 24 * 8);
    // Both sides of the face were met: directions that light the face and ones that do not.
    EXPECT_GT(lit, checked / 4);
    EXPECT_GT(dark, checked / 4);
}

}  // namespace
