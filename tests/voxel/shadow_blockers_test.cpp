// ShadowBlockers (src/voxel/shadow_blockers.h): the shadow rays it proves blocked are blocked by
// the exact walk (occluded), on terrain with floating blocks, from points on its faces, for
// bundles of directions a fraction of a degree to tens of degrees apart, and in a closed room
// for rays over the whole hemisphere; a proof short of a reach is never one short of where the
// walk stops, with faces kept over many points; a full set replaces its oldest face only when
// asked; and it proves nothing where its reasoning does not hold (rays along or away from the
// face, crossings on a voxel's edge, a crossing over an empty cell, a hit without a face).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "luxel/voxel/dda.h"
#include "terrain_with_blocks.h"
#include "voxel/shadow_blockers.h"

namespace luxel::voxel {
namespace {

constexpr Voxel kStone{128, 128, 128, 255};

TEST(ShadowBlockers, ProvesOnlyRaysTheWalkFindsBlocked) {
    const VoxelWorld world = terrainWithBlocks({64, 48, 64}, 7, 400);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0), signedUnit(-1.0, 1.0);
    int proofs = 0, blockedWalks = 0;
    for (int point = 0; point < 4000; ++point) {
        const Hit surface = hitFromAbove(world, rng);
        if (!surface.hit || surface.normal == Int3{}) continue;
        // A sun and a disk around it: spreads from 0.1 to 30 degrees.
        const Vec3d sun = normalised({signedUnit(rng), 0.05 + unit(rng), signedUnit(rng)});
        const double spread = 0.0017 + 0.52 * unit(rng) * unit(rng);
        ShadowBlockers blocker;
        for (int k = 0; k < 8; ++k) {
            const Vec3d l =
                normalised(sun + Vec3d{signedUnit(rng), signedUnit(rng), signedUnit(rng)} * spread);
            const Vec3d n{double(surface.normal.x), double(surface.normal.y),
                          double(surface.normal.z)};
            if (!(dot(l, n) > 0.0)) continue;
            const Ray ray{surface.point, l};
            const bool walked = occluded(world, ray);
            if (blocker.blocks(world, ray)) {
                ++proofs;
                ASSERT_TRUE(walked) << "point " << point << ", ray " << k;
                continue;
            }
            if (walked) {
                ++blockedWalks;
                blocker.note(castRay(world, ray));
            }
        }
    }
    // The proof must carry most of the blocked rays after the first of each point.
    EXPECT_GT(proofs, 2000);
    EXPECT_GT(blockedWalks, 500);
}

TEST(ShadowBlockers, ProveMostOfARoomsHemisphereRaysWithItsCeilingAndWalls) {
    // A closed room: a 20 x 12 x 20 shell with a pillar in it.
    VoxelWorld world = VoxelWorld::create({20, 12, 20}, 16).value();
    for (int x = 0; x < 20; ++x) {
        for (int y = 0; y < 12; ++y) {
            for (int z = 0; z < 20; ++z) {
                const bool shell = x == 0 || y == 0 || z == 0 || x == 19 || y == 11 || z == 19;
                const bool pillar = x >= 8 && x <= 10 && z >= 8 && z <= 9;
                if (shell || pillar) world.set(x, y, z, kStone);
            }
        }
    }
    world.refreshEmptySpace();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int proofs = 0, rays = 0;
    for (int point = 0; point < 300; ++point) {
        const Vec3d origin{1.0 + 18.0 * unit(rng), 1.0, 1.0 + 18.0 * unit(rng)};
        if (world.solid(int(origin.x), 1, int(origin.z))) continue;
        ShadowBlockers blockers;
        for (int k = 0; k < 16; ++k) {
            // Cosine-distributed about +y.
            const double r = std::sqrt(unit(rng)), phi = 6.283185307179586 * unit(rng);
            const Ray ray{origin, {r * std::cos(phi), std::sqrt(1.0 - r * r), r * std::sin(phi)}};
            ++rays;
            ASSERT_TRUE(occluded(world, ray));
            if (blockers.blocks(world, ray)) {
                ++proofs;
                continue;
            }
            blockers.note(castRay(world, ray));
        }
    }
    // The ceiling and four walls (and the pillar): all but the first four or five rays of each
    // point.
    EXPECT_GT(proofs, rays * 2 / 3) << proofs << " of " << rays;
}

TEST(ShadowBlockers, ProvesNoStopShortOfTheWalksOwn) {
    // The glossy lamps' rays ask for a stop short of the lamp's plane: the walk must stop no
    // later than any such proof says, with faces kept over many points (replacing the oldest).
    const VoxelWorld world = terrainWithBlocks({64, 48, 64}, 3, 400);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0), signedUnit(-1.0, 1.0);
    ShadowBlockers blockers;
    int proofs = 0, walks = 0;
    for (int point = 0; point < 12000; ++point) {
        const Hit surface = hitFromAbove(world, rng);
        if (!surface.hit || surface.normal == Int3{}) continue;
        const Vec3d n{double(surface.normal.x), double(surface.normal.y), double(surface.normal.z)};
        for (int k = 0; k < 4; ++k) {
            const Vec3d l = normalised({signedUnit(rng), signedUnit(rng), signedUnit(rng)});
            if (!(dot(l, n) > 0.0)) continue;
            const Ray ray{surface.point, l};
            const Hit walk = castRay(world, ray);
            if (walk.hit) {
                ++walks;
                ASSERT_FALSE(blockers.blocks(world, ray, walk.t - ShadowBlockers::kEdgeMargin))
                    << "point " << point << ", ray " << k;
                proofs += blockers.blocks(world, ray, walk.t + 1.0);
            } else {
                ASSERT_FALSE(blockers.blocks(world, ray));
            }
            blockers.note(walk, true);
        }
    }
    // Six planes kept over the whole terrain still prove a good share of the stops.
    EXPECT_GT(walks, 3000);
    EXPECT_GT(proofs, walks / 10) << proofs << " of " << walks;
}

// A slab of stone at y = 10 over the whole world; a ray from the floor at y = 2 hits its
// underside.
VoxelWorld slab() {
    VoxelWorld world = VoxelWorld::create({16, 16, 16}, 16).value();
    for (int x = 0; x < 16; ++x) {
        for (int z = 0; z < 16; ++z) {
            world.set(x, 10, z, kStone);
            world.set(x, 1, z, kStone);
        }
    }
    world.refreshEmptySpace();
    return world;
}

TEST(ShadowBlockers, ProvesNothingWhereItsReasonDoesNotHold) {
    const VoxelWorld world = slab();
    const Vec3d origin{4.3, 2.0, 4.6};
    const Hit up = castRay(world, {origin, normalised({0.1, 1.0, 0.05})});
    ASSERT_TRUE(up.hit);
    ASSERT_EQ(up.normal, (Int3{0, -1, 0}));
    ShadowBlockers blocker;
    EXPECT_FALSE(blocker.blocks(world, {origin, {0.0, 1.0, 0.0}}));  // nothing kept yet
    blocker.note(up);
    EXPECT_TRUE(blocker.blocks(world, {origin, normalised({-0.2, 1.0, 0.1})}));
    // Along the plane, away from it, or crossing it on a voxel's edge (x = 5 at y = 10).
    EXPECT_FALSE(blocker.blocks(world, {origin, {1.0, 0.0, 0.0}}));
    EXPECT_FALSE(blocker.blocks(world, {origin, normalised({0.1, -1.0, 0.0})}));
    EXPECT_FALSE(blocker.blocks(world, {origin, normalised({0.7 / 8.0, 1.0, 0.0})}));
    // A crossing over an empty cell of the slab.
    VoxelWorld holed = slab();
    holed.set(6, 10, 4, Voxel{});
    holed.refreshEmptySpace();
    EXPECT_FALSE(blocker.blocks(holed, {origin, normalised({1.9 / 8.0, 1.0, 0.0})}));
    EXPECT_FALSE(occluded(holed, {origin, normalised({1.9 / 8.0, 1.0, 0.0})}));
    // A crossing outside the world.
    EXPECT_FALSE(blocker.blocks(world, {origin, normalised({3.0, 1.0, 0.0})}));
}

TEST(ShadowBlockers, AFullSetReplacesItsOldestFaceOnlyWhenAsked) {
    const VoxelWorld world = slab();
    const Ray up{{4.3, 2.0, 4.6}, normalised({0.1, 1.0, 0.03})};
    const Hit underside = castRay(world, up);
    ASSERT_TRUE(underside.hit);
    // Six other planes: faces towards +x of voxels in columns 0..5 (empty or not; a kept face
    // is only a plane to test).
    const auto fill = [](ShadowBlockers& b, bool replace) {
        for (int x = 0; x < ShadowBlockers::kFaces; ++x) {
            Hit h;
            h.hit = true;
            h.voxel = {x, 5, 5};
            h.normal = {1, 0, 0};
            b.note(h, replace);
        }
    };
    ShadowBlockers kept, replaced;
    kept.note(underside);
    replaced.note(underside);
    fill(kept, false);
    fill(replaced, true);
    EXPECT_TRUE(kept.blocks(world, up));
    EXPECT_FALSE(replaced.blocks(world, up));
    EXPECT_TRUE(castRay(world, up).hit);
}

TEST(ShadowBlockers, KeepsNoHitWithoutAFace) {
    const VoxelWorld world = slab();
    Hit inside;
    inside.hit = true;
    inside.voxel = {3, 10, 3};
    ShadowBlockers blocker;
    blocker.note(inside);  // started inside a solid voxel: no face
    EXPECT_FALSE(blocker.blocks(world, {{4.3, 2.0, 4.6}, {0.0, 1.0, 0.0}}));
}

}  // namespace
}  // namespace luxel::voxel
