// Cutout texels: rays (primary, reflection, shadow) pass through them to what lies behind; the
// continuation matches the DDA through an empty voxel; the continuation cap; the texel tint.
#include "luxel/voxel/surface_cast.h"

#include <gtest/gtest.h>

#include <cmath>

#include "luxel/core/rng.h"
#include "luxel/core/tonemap.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shading.h"

namespace luxel::voxel {
namespace {

constexpr Voxel kWhite{255, 255, 255, 255};

Texture solidTexture(const std::string& name, Texel texel, int w = 1, int h = 1) {
    return Texture{name, w, h, std::vector<Texel>(static_cast<std::size_t>(w) * h, texel),
                   std::nullopt};
}

// Slot 0: every texel a cutout; slot 1: opaque, tinted (0.5, 1, 0.25); slot 2: left half
// (u < 0.5) cutout, right half opaque.
TextureSet testTextures() {
    TextureSet set;
    EXPECT_TRUE(set.add(solidTexture("holes", {1, 1, 1, 0})).ok());
    EXPECT_TRUE(set.add(solidTexture("tint", {0.5f, 1.0f, 0.25f, 1})).ok());
    Texture half = solidTexture("half", {1, 1, 1, 1}, 2, 1);
    half.texels[0].a = 0.0f;
    EXPECT_TRUE(set.add(half).ok());
    return set;
}

TEST(SurfaceCast, CutoutLetsTheRayThroughToTheVoxelBehind) {
    const TextureSet textures = testTextures();
    VoxelWorld world = VoxelWorld::create({8, 4, 8}, 4).value();
    world.set(2, 1, 4, Voxel{255, 255, 255, alphaForSlot(0)});
    world.set(5, 1, 4, kWhite);
    const Ray ray{{0.5, 1.5, 4.5}, {1, 0, 0}};
    const SurfaceHit s = castToSurface(world, &textures, ray);
    ASSERT_TRUE(s.hit.hit);
    EXPECT_EQ(s.hit.voxel, (Int3{5, 1, 4}));
    EXPECT_EQ(s.hit.normal, (Int3{-1, 0, 0}));
    EXPECT_EQ(s.hit.t, 4.5);
    EXPECT_EQ(s.continuations, 1);
    EXPECT_EQ(s.slot, -1);
    // Without the texture set the same voxel is a plain block and stops the ray.
    EXPECT_EQ(castToSurface(world, nullptr, ray).hit.voxel, (Int3{2, 1, 4}));
    // An opaque texture stops it and reports the texel.
    world.set(2, 1, 4, Voxel{255, 255, 255, alphaForSlot(1)});
    const SurfaceHit opaque = castToSurface(world, &textures, ray);
    EXPECT_EQ(opaque.hit.voxel, (Int3{2, 1, 4}));
    EXPECT_EQ(opaque.slot, 1);
    EXPECT_EQ(opaque.texel, (Texel{0.5f, 1.0f, 0.25f, 1}));
    EXPECT_EQ(opaque.continuations, 0);
}

TEST(SurfaceCast, HolesFollowTheTexelUnderTheHit) {
    const TextureSet textures = testTextures();
    VoxelWorld world = VoxelWorld::create({8, 4, 8}, 4).value();
    world.set(2, 1, 4, Voxel{255, 255, 255, alphaForSlot(2)});
    world.set(5, 1, 4, kWhite);
    // On an x face u runs along z: z = 4.25 is in the cutout half, z = 4.75 in the opaque one.
    EXPECT_EQ(castToSurface(world, &textures, {{0.5, 1.5, 4.25}, {1, 0, 0}}).hit.voxel,
              (Int3{5, 1, 4}));
    EXPECT_EQ(castToSurface(world, &textures, {{0.5, 1.5, 4.75}, {1, 0, 0}}).hit.voxel,
              (Int3{2, 1, 4}));
}

// Cutout voxels behave exactly like empty voxels for rays in any direction, including rays
// through edges and corners: the continuation takes the cell the DDA would step to next.
TEST(SurfaceCast, FullCutoutsMatchEmptyVoxelsForRandomRays) {
    const TextureSet textures = testTextures();
    VoxelWorld withCutouts = VoxelWorld::create({24, 24, 24}, 8).value();
    VoxelWorld withoutThem = VoxelWorld::create({24, 24, 24}, 8).value();
    Pcg32 rng(7);
    for (int z = 0; z < 24; ++z) {
        for (int y = 0; y < 24; ++y) {
            for (int x = 0; x < 24; ++x) {
                const double u = rng.nextDouble();
                if (u < 0.02) {
                    withCutouts.set(x, y, z, kWhite);
                    withoutThem.set(x, y, z, kWhite);
                } else if (u < 0.2) {
                    withCutouts.set(x, y, z, Voxel{255, 255, 255, alphaForSlot(0)});
                }
            }
        }
    }
    int hits = 0, checked = 0;
    for (int i = 0; i < 4000; ++i) {
        // Half the rays start on lattice points and go along lattice diagonals (edge and corner
        // crossings), half are random.
        Ray ray;
        if (i % 2 == 0) {
            ray.origin = {double(1 + (rng.next() % 22)), double(1 + (rng.next() % 22)),
                          double(1 + (rng.next() % 22))};
            ray.direction = {double((rng.next() % 3)) - 1, double((rng.next() % 3)) - 1,
                             double((rng.next() % 3)) - 1};
            if (ray.direction == Vec3d{}) ray.direction = {1, 1, 0};
        } else {
            ray.origin = {rng.nextDouble() * 24, rng.nextDouble() * 24, rng.nextDouble() * 24};
            ray.direction = {rng.nextDouble() - 0.5, rng.nextDouble() - 0.5,
                             rng.nextDouble() - 0.5};
        }
        const Hit expected = castRay(withoutThem, ray);
        const SurfaceHit got = castToSurface(withCutouts, &textures, ray);
        if (got.cutoutCapped) continue;
        ++checked;
        ASSERT_EQ(got.hit.hit, expected.hit)
            << i << ": origin " << ray.origin.x << " " << ray.origin.y << " " << ray.origin.z
            << " direction " << ray.direction.x << " " << ray.direction.y << " " << ray.direction.z
            << " continuations " << got.continuations << " expected voxel " << expected.voxel.x
            << " " << expected.voxel.y << " " << expected.voxel.z;
        if (!expected.hit) continue;
        ++hits;
        EXPECT_EQ(got.hit.voxel, expected.voxel) << i;
        // An origin inside a cutout voxel has no entry face (normal 0); past a continuation the
        // entry face is known.
        if (got.continuations == 0 || expected.normal != Int3{}) {
            EXPECT_EQ(got.hit.normal, expected.normal) << i;
        }
        EXPECT_NEAR(got.hit.t, expected.t, 1e-9 * (1 + expected.t)) << i;
    }
    EXPECT_GT(checked, 3900);
    EXPECT_GT(hits, 1000);
}

TEST(SurfaceCast, ContinuationsAreCapped) {
    const TextureSet textures = testTextures();
    VoxelWorld world = VoxelWorld::create({80, 2, 2}, 4).value();
    for (int x = 0; x < 70; ++x) world.set(x, 0, 0, Voxel{255, 255, 255, alphaForSlot(0)});
    world.set(79, 0, 0, kWhite);
    const SurfaceHit capped = castToSurface(world, &textures, {{-1, 0.5, 0.5}, {1, 0, 0}});
    EXPECT_FALSE(capped.hit.hit);
    EXPECT_TRUE(capped.cutoutCapped);
    EXPECT_EQ(capped.continuations, kMaxCutoutContinuations);
    for (int x = 10; x < 70; ++x) world.set(x, 0, 0, Voxel{});
    const SurfaceHit through = castToSurface(world, &textures, {{-1, 0.5, 0.5}, {1, 0, 0}});
    EXPECT_TRUE(through.hit.hit);
    EXPECT_EQ(through.hit.voxel, (Int3{79, 0, 0}));
    EXPECT_EQ(through.continuations, 10);
}

// A floor under a one-voxel-thick canopy, sun straight up: the floor is shadowed under an opaque
// canopy and lit under a cutout one (shadow rays pass through holes).
TEST(SurfaceCast, ShadowRaysPassThroughHoles) {
    const TextureSet textures = testTextures();
    VoxelWorld world = VoxelWorld::create({16, 8, 16}, 8).value();
    for (int z = 0; z < 16; ++z) {
        for (int x = 0; x < 16; ++x) {
            world.set(x, 0, z, Voxel{180, 180, 180, 255});
            world.set(x, 5, z, Voxel{255, 255, 255, alphaForSlot(1)});  // opaque canopy
        }
    }
    ShadeOptions options;
    options.sunDirection = {0, 1, 0};
    options.maxReflections = 0;
    options.textures = false;
    // From under the canopy, down onto the floor at (8.5, 1, 8.5).
    const Ray ray{{2.5, 3.0, 8.5}, {6.0, -2.0, 0.0}};
    const Rgb shadowed = shadeRay(world, ray, options, &textures);
    for (int z = 0; z < 16; ++z) {
        for (int x = 0; x < 16; ++x) world.set(x, 5, z, Voxel{255, 255, 255, alphaForSlot(0)});
    }
    const Rgb lit = shadeRay(world, ray, options, &textures);
    // Top face, sun (0, 1, 0): lit min((1 + 1) / 2 + 0.1, 1) = 1, shadowed (0 + 1) / 2 + 0.1.
    EXPECT_NEAR(shadowed.r / lit.r, 0.6f, 1e-6);
    EXPECT_NEAR(lit.r, srgbToLinear(180 / 255.0f), 1e-6);
}

TEST(SurfaceCast, TexelTintsTheVoxelColour) {
    const TextureSet textures = testTextures();
    VoxelWorld world = VoxelWorld::create({4, 4, 4}, 4).value();
    world.set(2, 1, 1, Voxel{255, 255, 255, alphaForSlot(1)});
    world.set(2, 2, 1, Voxel{255, 128, 255, alphaForSlot(1)});
    ShadeOptions options;
    options.faceShading = false;
    options.maxReflections = 0;
    const Rgb white = shadeRay(world, {{0.5, 1.5, 1.5}, {1, 0, 0}}, options, &textures);
    EXPECT_NEAR(white.r, 0.5f, 1e-6);
    EXPECT_NEAR(white.g, 1.0f, 1e-6);
    EXPECT_NEAR(white.b, 0.25f, 1e-6);
    const Rgb tinted = shadeRay(world, {{0.5, 2.5, 1.5}, {1, 0, 0}}, options, &textures);
    EXPECT_NEAR(tinted.g, srgbToLinear(128 / 255.0f), 1e-6);
    // Procedural texture modulation applies to plain blocks only.
    EXPECT_NEAR(tinted.r, 0.5f, 1e-6);
}

TEST(SurfaceCast, TextureReflectivityOverridesTheDefault) {
    TextureSet textures;
    Texture mirror = solidTexture("mirror", {1, 1, 1, 1});
    mirror.reflectivity = 1.0f;
    ASSERT_TRUE(textures.add(mirror).ok());
    VoxelWorld world = VoxelWorld::create({4, 4, 4}, 4).value();
    world.set(2, 1, 1, Voxel{255, 0, 0, alphaForSlot(0)});
    ShadeOptions options;
    options.reflectionMode = ShadeOptions::ReflectionMode::EnergyConserving;
    options.reflectivity = 0.0f;
    options.maxReflections = 1;
    options.faceShading = false;
    // A perfect mirror shows only what it reflects: the sky behind the ray (at the horizon).
    const Rgb seen = shadeRay(world, {{0.5, 1.5, 1.5}, {1, 0, 0}}, options, &textures);
    EXPECT_NEAR(seen.r, options.skyHorizon.r, 1e-6);
    EXPECT_NEAR(seen.b, options.skyHorizon.b, 1e-6);
}

}  // namespace
}  // namespace luxel::voxel
