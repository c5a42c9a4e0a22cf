// Filtered face textures: mip chains, trilinear and anisotropic sampling against brute-force
// footprint integrals, level selection, normal maps, and ray-cone footprints against rays cast
// through the cone's edge.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "gpu/shaders/shared/texture_filter.h"
#include "luxel/voxel/dda.h"
#include "luxel/voxel/texel_footprint.h"
#include "luxel/voxel/texture_set.h"

namespace luxel::voxel {
namespace {

namespace shared = gpu::shared;

Texture textureOf(const std::string& name, int w, int h, auto&& value) {
    Texture t{name, w, h, {}, std::nullopt};
    for (int row = 0; row < h; ++row) {
        for (int column = 0; column < w; ++column) t.texels.push_back(value(column, row));
    }
    return t;
}

// Checkerboard of 0 and 1 in every colour channel, `cells` texels per square.
Texture checker(int side, int cells = 1) {
    return textureOf("checker", side, side, [&](int c, int r) {
        const float x = float(((c / cells) + (r / cells)) % 2);
        return Texel{x, x, x, 1};
    });
}

// Smooth structure at several scales (periods of 3 to 16 texels, random phases): the kind of
// signal a footprint integral keeps part of.
Texture waves(int side, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> phase(0.0f, 6.2831853f);
    struct Wave {
        float kx, ky, p;
    };
    std::vector<Wave> w;
    for (float period : {3.0f, 5.0f, 8.0f, 16.0f}) {
        const float a = phase(rng);
        const float k = 6.2831853f / period;
        // Periods that tile the texture, so wrapping adds no seam.
        w.push_back({std::round(k * std::cos(a) * side / 6.2831853f) * 6.2831853f / side,
                     std::round(k * std::sin(a) * side / 6.2831853f) * 6.2831853f / side,
                     phase(rng)});
    }
    return textureOf("waves", side, side, [&](int c, int r) {
        float x = 0.5f;
        for (const Wave& v : w) x += 0.12f * std::sin(v.kx * c + v.ky * r + v.p);
        return Texel{x, x, x, 1};
    });
}

// The mean of the level-0 texels (nearest, wrapped) over the footprint ellipse centred at (u, v),
// by stratified points: the integral the filters approximate.
float footprintIntegral(const TextureSet& set, int slot, float u, float v,
                        const TexelFootprint& f) {
    const int n = 96;
    double sum = 0;
    int count = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double a = 2.0 * (i + 0.5) / n - 1.0, b = 2.0 * (j + 0.5) / n - 1.0;
            if (a * a + b * b > 1.0) continue;
            double fu = u + a * f.majorU + b * f.minorU;
            double fv = v + a * f.majorV + b * f.minorV;
            fu -= std::floor(fu);
            fv -= std::floor(fv);
            sum += set.lookup(slot, float(fu), float(fv)).r;
            ++count;
        }
    }
    return float(sum / count);
}

TexelFootprint ellipse(float major, float minor, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return {major * c, major * s, -minor * s, minor * c};
}

TEST(TextureFilter, MipChainSizesAndOffsets) {
    EXPECT_EQ(shared::textureLevelCount(1, 1), 1);
    EXPECT_EQ(shared::textureLevelCount(16, 16), 5);
    EXPECT_EQ(shared::textureLevelCount(7, 3), 3);  // 7x3, 3x1, 1x1
    EXPECT_EQ(shared::textureLevelSide(7, 1), 3);
    EXPECT_EQ(shared::textureLevelSide(3, 2), 1);
    EXPECT_EQ(shared::textureLevelOffset(7, 3, 1), 21u);
    EXPECT_EQ(shared::textureLevelOffset(7, 3, 2), 24u);
    EXPECT_EQ(shared::textureChainTexels(7, 3), 25u);
    TextureSet set;
    ASSERT_TRUE(set.add(checker(7)));
    EXPECT_EQ(set.mipLevels(0), 3);
    EXPECT_EQ(set.colourMips(0).size(), shared::textureChainTexels(7, 7));
}

// Box filtering with exact area weights keeps the mean on every level, odd sides included.
TEST(TextureFilter, EveryMipLevelKeepsTheMean) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> x(0.0f, 1.0f);
    for (auto [w, h] : {std::pair{16, 16}, {13, 7}, {5, 1}, {1, 9}}) {
        TextureSet set;
        ASSERT_TRUE(set.add(textureOf("r", w, h, [&](int, int) {
            return Texel{x(rng), x(rng), x(rng), 1};
        })));
        const auto& chain = set.colourMips(0);
        double mean0 = 0;
        for (int i = 0; i < w * h; ++i) mean0 += chain[i].g;
        mean0 /= w * h;
        for (int l = 1; l < set.mipLevels(0); ++l) {
            const int lw = shared::textureLevelSide(w, l), lh = shared::textureLevelSide(h, l);
            const std::size_t off = shared::textureLevelOffset(w, h, l);
            double mean = 0;
            for (int i = 0; i < lw * lh; ++i) mean += chain[off + i].g;
            EXPECT_NEAR(mean / (lw * lh), mean0, 1e-5) << w << "x" << h << " level " << l;
        }
    }
}

TEST(TextureFilter, ConstantTextureFiltersToItself) {
    TextureSet set;
    const Texel c{0.3f, 0.5f, 0.7f, 1.0f};
    ASSERT_TRUE(set.add(textureOf("c", 12, 5, [&](int, int) { return c; })));
    for (TextureFilter filter : {TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
        for (float major : {0.0f, 0.01f, 0.1f, 0.5f, 3.0f, 40.0f}) {
            for (float ratio : {1.0f, 3.0f, 17.0f}) {
                const TexelFootprint f = ellipse(major, major / ratio, 0.7f);
                const Texel t = set.sample(0, 0.37f, 0.91f, f, filter);
                EXPECT_NEAR(t.r, c.r, 1e-5f);
                EXPECT_NEAR(t.g, c.g, 1e-5f);
                EXPECT_NEAR(t.b, c.b, 1e-5f);
                EXPECT_NEAR(t.a, c.a, 1e-5f);
            }
        }
    }
}

TEST(TextureFilter, PointFootprintIsBilinearOnLevelZero) {
    TextureSet set;
    ASSERT_TRUE(set.add(checker(4)));
    // At a texel centre the bilinear weights are (1, 0, 0, 0): the texel itself.
    for (TextureFilter filter : {TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
        EXPECT_EQ(set.sample(0, 0.125f, 0.375f, {}, filter), set.lookup(0, 0.125f, 0.375f));
    }
    // Halfway between two texel centres, the mean of a 0 and a 1.
    EXPECT_NEAR(set.sample(0, 0.25f, 0.375f, {}, TextureFilter::Trilinear).r, 0.5f, 1e-6f);
}

TEST(TextureFilter, CheckerboardOverALargeFootprintConvergesToItsMean) {
    TextureSet set;
    ASSERT_TRUE(set.add(checker(16)));
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> pos(0.0f, 1.0f);
    for (TextureFilter filter : {TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
        for (int i = 0; i < 50; ++i) {
            const TexelFootprint f = ellipse(3.0f, 1.5f, pos(rng) * 3.0f);
            EXPECT_NEAR(set.sample(0, pos(rng), pos(rng), f, filter).r, 0.5f, 1e-4f);
        }
    }
}

// The wider the footprint, the coarser the level and the closer to the mean: the RMS deviation
// of a filtered fine checkerboard from its mean falls as the footprint grows.
TEST(TextureFilter, LevelSelectionIsMonotoneInTheFootprint) {
    float previousLod = -1e9f;
    for (float d = 0.01f; d < 5000.0f; d *= 1.3f) {
        const float lod = shared::textureLod(d);
        EXPECT_GT(lod, previousLod);
        previousLod = lod;
    }
    EXPECT_NEAR(shared::textureLod(1.0f), 0.0f, 1e-6f);
    EXPECT_NEAR(shared::textureLod(8.0f), 3.0f, 1e-5f);

    TextureSet set;
    ASSERT_TRUE(set.add(checker(32)));
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> pos(0.0f, 1.0f);
    std::vector<std::pair<float, float>> points(200);
    for (auto& p : points) p = {pos(rng), pos(rng)};
    float previous = 1e9f;
    for (float radiusTexels = 0.5f; radiusTexels <= 32.0f; radiusTexels *= 1.5f) {
        const float r = radiusTexels / 32.0f;
        double sq = 0;
        for (auto [u, v] : points) {
            const float x = set.sample(0, u, v, ellipse(r, r, 0.0f), TextureFilter::Trilinear).r;
            sq += (x - 0.5) * (x - 0.5);
        }
        const float rms = float(std::sqrt(sq / points.size()));
        EXPECT_LE(rms, previous + 1e-6f) << "radius " << radiusTexels << " texels";
        previous = rms;
    }
    EXPECT_LT(previous, 1e-3f);
}

TEST(TextureFilter, ProbeCount) {
    EXPECT_EQ(shared::textureProbeCount(1.0f, 1.0f, 16), 1);
    EXPECT_EQ(shared::textureProbeCount(4.0f, 1.0f, 16), 4);
    EXPECT_EQ(shared::textureProbeCount(4.5f, 1.0f, 16), 5);
    EXPECT_EQ(shared::textureProbeCount(100.0f, 1.0f, 16), 16);
    EXPECT_EQ(shared::textureProbeCount(100.0f, 1.0f, 1), 1);
    EXPECT_EQ(shared::textureProbeCount(1.0f, 0.0f, 8), 8);
    EXPECT_EQ(shared::textureProbeCount(0.0f, 0.0f, 8), 1);
    EXPECT_NEAR(shared::textureProbeOffset(0, 4), -0.75f, 1e-7f);
    EXPECT_NEAR(shared::textureProbeOffset(3, 4), 0.75f, 1e-7f);
    EXPECT_NEAR(shared::textureProbeOffset(0, 1), 0.0f, 1e-7f);
}

// Grazing footprints (major / minor = 8): the probes along the major axis follow the ellipse,
// while the isotropic trilinear lookup blurs over a disc as wide as the major axis.
TEST(TextureFilter, AnisotropicProbesBeatTrilinearAtGrazingFootprints) {
    const int side = 64;
    TextureSet set;
    ASSERT_TRUE(set.add(waves(side, 21)));
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> pos(0.0f, 1.0f);
    double triSq = 0, anisoSq = 0, anisoCappedSq = 0;
    const int n = 200;
    for (int i = 0; i < n; ++i) {
        const float minorTexels = 0.75f + 1.5f * pos(rng);
        const TexelFootprint f =
            ellipse(8.0f * minorTexels / side, minorTexels / side, pos(rng) * 3.14159f);
        const float u = pos(rng), v = pos(rng);
        const float truth = footprintIntegral(set, 0, u, v, f);
        const float tri = set.sample(0, u, v, f, TextureFilter::Trilinear).r;
        const float aniso = set.sample(0, u, v, f, TextureFilter::Anisotropic, 16).r;
        const float capped = set.sample(0, u, v, f, TextureFilter::Anisotropic, 2).r;
        triSq += (tri - truth) * (tri - truth);
        anisoSq += (aniso - truth) * (aniso - truth);
        anisoCappedSq += (capped - truth) * (capped - truth);
    }
    const double tri = std::sqrt(triSq / n), aniso = std::sqrt(anisoSq / n),
                 capped = std::sqrt(anisoCappedSq / n);
    std::printf("footprint-integral RMSE: trilinear %.4f, anisotropic x2 %.4f, x16 %.4f\n", tri,
                capped, aniso);
    EXPECT_LT(aniso, 0.5 * tri);
    EXPECT_LT(aniso, capped);
    EXPECT_LT(capped, tri);
}

// Premultiplied mips: transparent texels do not darken the filtered colour of the opaque ones.
TEST(TextureFilter, TransparentTexelsAddNoColour) {
    TextureSet set;
    ASSERT_TRUE(set.add(textureOf("leaf", 8, 8, [](int c, int) {
        return c % 2 ? Texel{0, 0, 0, 0} : Texel{0.2f, 0.8f, 0.1f, 1};
    })));
    const Texel t = set.sample(0, 0.3f, 0.4f, ellipse(0.5f, 0.5f, 0.0f), TextureFilter::Trilinear);
    EXPECT_NEAR(t.g, 0.8f, 1e-5f);
    EXPECT_NEAR(t.a, 0.5f, 1e-5f);
}

TEST(TextureFilter, NormalMapsFilterAndRenormalise) {
    TextureSet set;
    Texture flat = checker(4);
    ASSERT_TRUE(set.add(flat));
    EXPECT_FALSE(set.hasNormalMap(0));
    EXPECT_EQ(set.normalAt(0, 0.5f, 0.5f, {}, TextureFilter::Anisotropic), (Vec3{0, 0, 1}));
    // Columns tilted alternately towards +u and -u: nearest keeps the tilt, a wide footprint
    // averages it away (renormalised to the face normal).
    Texture bumpy = checker(4);
    bumpy.name = "bumpy";
    const float s = std::sqrt(0.5f);
    for (int i = 0; i < 16; ++i) bumpy.normals.push_back({i % 2 ? s : -s, 0, s, 1});
    ASSERT_TRUE(set.add(bumpy));
    EXPECT_TRUE(set.hasNormalMap(1));
    const Vec3 n = set.normalAt(1, 0.3f, 0.5f, {}, TextureFilter::Nearest);
    EXPECT_NEAR(n.x, s, 1e-6f);
    EXPECT_NEAR(length(n), 1.0f, 1e-6f);
    const Vec3 wide = set.normalAt(1, 0.3f, 0.5f, ellipse(2, 2, 0), TextureFilter::Trilinear);
    EXPECT_NEAR(wide.x, 0.0f, 1e-5f);
    EXPECT_NEAR(wide.z, 1.0f, 1e-5f);
    // A normal map of the wrong size or with NaN is refused.
    Texture bad = checker(4);
    bad.name = "bad";
    bad.normals.assign(3, Texel{});
    EXPECT_FALSE(set.add(bad));
    bad.normals.assign(16, Texel{std::nanf(""), 0, 1, 1});
    EXPECT_FALSE(set.add(bad));
}

TEST(TextureFilter, FilterNames) {
    for (TextureFilter f :
         {TextureFilter::Nearest, TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
        EXPECT_EQ(parseTextureFilter(textureFilterName(f)), f);
    }
    EXPECT_FALSE(parseTextureFilter("bilinear"));
}

// The footprint against brute force: rays through the edge of the cone's cross-section (a
// cylinder at this scale), cast at a voxel with the real traversal, land on the face at (u, v)
// offsets that lie on the footprint ellipse, for all six faces.
TEST(TexelFootprint, MatchesRaysCastThroughTheConeEdge) {
    VoxelWorld world = VoxelWorld::create({8, 8, 8}, 8).value();
    world.set(4, 4, 4, Voxel{200, 200, 200, 255});
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> x(-1.0, 1.0);
    const Vec3d centre{4.5, 4.5, 4.5};
    int checked = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign : {-1, 1}) {
            for (int trial = 0; trial < 20; ++trial) {
                Int3 normal{};
                normal[axis] = sign;
                // A direction into the face at incidence cosines down to 0.3.
                Vec3d d{x(rng), x(rng), x(rng)};
                d[axis] = -sign * (0.3 + 0.7 * std::abs(x(rng))) * 2.0;
                d = normalize(d);
                if (std::abs(d[axis]) < 0.3) continue;
                Vec3d target = centre;
                target[axis] += 0.5 * sign;
                target = target + Vec3d{x(rng), x(rng), x(rng)} * 0.1;
                target[axis] = centre[axis] + 0.5 * sign;
                const Vec3d origin = target - d * 3.0;
                const RayCone cone{0.02, 0.01};  // width 0.05 at t = 3
                const Hit hit = castRay(world, {origin, d});
                ASSERT_TRUE(hit.hit);
                ASSERT_EQ(hit.normal, normal);
                const TexelFootprint f = texelFootprint(cone, hit.t, d, hit.normal);
                const double r = 0.5 * cone.widthAt(hit.t);
                EXPECT_NEAR(std::hypot(f.minorU, f.minorV), r, 1e-6);
                EXPECT_NEAR(std::hypot(f.majorU, f.majorV), r / std::abs(d[axis]), 1e-5);
                // Two unit vectors perpendicular to d.
                Vec3d e1 =
                    normalize(cross(d, std::abs(d.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0}));
                Vec3d e2 = cross(d, e1);
                const double mm = f.majorU * f.majorU + f.majorV * f.majorV;
                const double nn = f.minorU * f.minorU + f.minorV * f.minorV;
                for (int k = 0; k < 16; ++k) {
                    const double phi = 2.0 * std::numbers::pi * k / 16;
                    const Vec3d o = origin + (e1 * std::cos(phi) + e2 * std::sin(phi)) * r;
                    const Hit h = castRay(world, {o, d});
                    ASSERT_TRUE(h.hit);
                    ASSERT_EQ(h.normal, normal);
                    const double du = h.u - hit.u, dv = h.v - hit.v;
                    // Coordinates in the footprint's axes: on the ellipse, a^2 + b^2 = 1.
                    const double a = (du * f.majorU + dv * f.majorV) / mm;
                    const double b = (du * f.minorU + dv * f.minorV) / nn;
                    EXPECT_NEAR(a * a + b * b, 1.0, 2e-3) << "axis " << axis << " sign " << sign;
                }
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 60);
}

TEST(TexelFootprint, HeadOnAndDegenerateCases) {
    const RayCone cone{0.0, 0.01};
    const TexelFootprint f = texelFootprint(cone, 10.0, {0, -1, 0}, {0, 1, 0});
    EXPECT_NEAR(std::hypot(f.majorU, f.majorV), 0.05, 1e-7);
    EXPECT_NEAR(std::hypot(f.minorU, f.minorV), 0.05, 1e-7);
    const TexelFootprint none = texelFootprint(cone, 10.0, {0, -1, 0}, {0, 0, 0});
    EXPECT_EQ(none.majorU, 0.0f);
    EXPECT_EQ(none.minorV, 0.0f);
    // Exactly grazing: the major axis stops growing at 1 / LUXEL_TEXTURE_MIN_COS.
    const TexelFootprint g = texelFootprint(cone, 10.0, {1, 0, 0}, {0, 1, 0});
    EXPECT_TRUE(std::isfinite(g.majorU));
    EXPECT_NEAR(g.majorU, 0.05 / 1e-4, 1.0);
}

}  // namespace
}  // namespace luxel::voxel
