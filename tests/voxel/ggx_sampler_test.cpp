// GgxSampler (src/voxel/path_trace_bsdf.h): the real-time solvers' GGX reflection directions,
// with the lobe's frame made once, are sampleBsdf's to the bit (the same directions, weights and
// lobes, drawing the same numbers), over every face normal, many views and roughnesses, and
// within float rounding of the path tracer's double samples; a lobe that is not specular-only
// goes to sampleBsdf itself.
#include <gtest/gtest.h>

#include <cmath>

#include "luxel/voxel/path_trace_rng.h"
#include "voxel/path_trace_bsdf.h"

namespace {

using namespace luxel;
using namespace luxel::voxel;

void expectSame(const BsdfSample& a, const BsdfSample& b) {
    ASSERT_EQ(int(a.lobe), int(b.lobe));
    if (a.lobe == BsdfSample::Lobe::None) return;
    ASSERT_EQ(a.direction.x, b.direction.x);
    ASSERT_EQ(a.direction.y, b.direction.y);
    ASSERT_EQ(a.direction.z, b.direction.z);
    ASSERT_EQ(a.weight.r, b.weight.r);
    ASSERT_EQ(a.weight.g, b.weight.g);
    ASSERT_EQ(a.weight.b, b.weight.b);
}

// A specular-only GGX lobe on the face of normal n, seen from a random direction of `views`
// flipped into the face's side and tilted a little off the face.
PathBsdf specularLobe(Int3 n, float roughness, PathRng& views) {
    Vec3d view{2.0 * views.next() - 1.0, 2.0 * views.next() - 1.0, 2.0 * views.next() - 1.0};
    const Vec3d nd{double(n.x), double(n.y), double(n.z)};
    if (dot(view, nd) < 0.0) view = view - nd * (2.0 * dot(view, nd));
    view = normalize(view + nd * 0.05);
    PathBsdf b;
    b.normal = n;
    b.view = view;
    b.cosView = dot(nd, view);
    b.alpha = roughness * roughness;
    b.specular = Rgb(1.0f);
    b.pSpecular = 1.0;
    return b;
}

TEST(GgxSampler, DrawsSampleBsdfsDirectionsAndWeights) {
    const Int3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    PathRng views(7, 0, 0);
    int drawn = 0, below = 0;
    for (const Int3 n : normals) {
        for (const float roughness : {0.12f, 0.4f, 0.7f, 1.0f}) {
            for (int v = 0; v < 16; ++v) {
                const PathBsdf b = specularLobe(n, roughness, views);
                const GgxSampler sampler(b);
                PathRng a(11, std::uint64_t(drawn), 0), c(11, std::uint64_t(drawn), 0);
                for (int k = 0; k < 4; ++k) {
                    const BsdfSample fromSampler = sampler.sample(a);
                    const BsdfSample fromBsdf = sampleBsdf(b, c, false);
                    expectSame(fromSampler, fromBsdf);
                    if (fromSampler.lobe == BsdfSample::Lobe::None) ++below;
                    ++drawn;
                }
                // Both drew the same numbers.
                ASSERT_EQ(a.next(), c.next());
            }
        }
    }
    EXPECT_EQ(drawn, 6 * 4 * 16 * 4);
    EXPECT_LT(below, drawn / 2);
}

// The solvers' float directions and weights are the path tracer's double ones for the same
// numbers, to float rounding, down to the narrowest glossy lobes (roughness 0.02).
TEST(GgxSampler, FloatSamplesAreTheDoubleOnes) {
    const Int3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    PathRng views(5, 0, 0);
    int compared = 0;
    for (const Int3 n : normals) {
        for (const float roughness : {0.02f, 0.12f, 0.4f, 1.0f}) {
            for (int v = 0; v < 16; ++v) {
                const PathBsdf b = specularLobe(n, roughness, views);
                const GgxSampler sampler(b);
                for (int k = 0; k < 4; ++k) {
                    PathRng a(13, std::uint64_t(v), std::uint64_t(k));
                    PathRng c(13, std::uint64_t(v), std::uint64_t(k));
                    const BsdfSample f = sampler.sample(a);
                    const BsdfSample d = sampleBsdf(b, c, true);
                    // Only a direction within rounding of the horizon may fall on either side.
                    if (int(f.lobe) != int(d.lobe)) {
                        const Vec3d nd{double(n.x), double(n.y), double(n.z)};
                        EXPECT_LT(std::abs(dot(nd, d.direction)), 1e-5) << roughness;
                        continue;
                    }
                    if (d.lobe == BsdfSample::Lobe::None) continue;
                    EXPECT_NEAR(length(f.direction), 1.0, 1e-6);
                    EXPECT_NEAR(f.direction.x, d.direction.x, 2e-5) << roughness;
                    EXPECT_NEAR(f.direction.y, d.direction.y, 2e-5) << roughness;
                    EXPECT_NEAR(f.direction.z, d.direction.z, 2e-5) << roughness;
                    EXPECT_NEAR(f.weight.r, d.weight.r, 1e-4) << roughness;  // in [0, 1]
                    ++compared;
                }
            }
        }
    }
    EXPECT_GT(compared, 6 * 4 * 16 * 4 / 2);
}

TEST(GgxSampler, OtherLobesGoToSampleBsdf) {
    PathBsdf b;
    b.normal = {0, 1, 0};
    b.view = normalize(Vec3d{0.3, 0.9, 0.1});
    b.cosView = b.view.y;
    b.alpha = 0.3f;
    b.specular = Rgb(0.2f);
    b.diffuse = Rgb(0.5f);
    b.pSpecular = 0.3;
    b.pDiffuse = 0.7;
    const GgxSampler sampler(b);
    PathRng a(3, 4, 5), c(3, 4, 5);
    int diffuse = 0;
    for (int k = 0; k < 64; ++k) {
        const BsdfSample fromSampler = sampler.sample(a);
        expectSame(fromSampler, sampleBsdf(b, c, false));
        if (fromSampler.lobe == BsdfSample::Lobe::Diffuse) ++diffuse;
    }
    EXPECT_GT(diffuse, 0);
}

}  // namespace
