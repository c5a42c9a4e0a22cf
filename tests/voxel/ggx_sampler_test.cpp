// GgxSampler (src/voxel/path_trace_bsdf.h): the real-time solvers' GGX reflection directions,
// with the lobe's frame made once, are sampleBsdf's to the bit (the same directions, weights and
// lobes, drawing the same numbers), over every face normal, many views and roughnesses; a lobe
// that is not specular-only goes to sampleBsdf itself.
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

TEST(GgxSampler, DrawsSampleBsdfsDirectionsAndWeights) {
    const Int3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    PathRng views(7, 0, 0);
    int drawn = 0, below = 0;
    for (const Int3 n : normals) {
        for (const float roughness : {0.12f, 0.4f, 0.7f, 1.0f}) {
            for (int v = 0; v < 16; ++v) {
                // A view on the face's side: a random direction flipped into its hemisphere.
                Vec3d view{2.0 * views.next() - 1.0, 2.0 * views.next() - 1.0,
                           2.0 * views.next() - 1.0};
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
