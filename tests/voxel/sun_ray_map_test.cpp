// SunRayMap (src/voxel/sun_ray_map.h): every shadow ray it proves open reaches the sky by the
// exact walk, on terrain with floating blocks and glass, for suns from overhead to grazing and
// disks from a point to 17 degrees, from points anywhere on every face (edges and corners too,
// faces between two solid voxels included); it proves most of the lit rays of an open floor; and
// the sun's light at a surface is the same to the bit with the map as without; the start
// cells asked for only where a proof needs them change no answer.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "luxel/voxel/dda.h"
#include "terrain_with_blocks.h"
#include "voxel/path_trace_bsdf.h"
#include "voxel/solver_sun.h"
#include "voxel/sun_disk.h"
#include "voxel/sun_ray_map.h"

namespace luxel::voxel {
namespace {

constexpr Voxel kStone{128, 128, 128, 255};

TEST(SunRayMap, ProvesOnlyRaysTheWalkFindsOpenOrBlocked) {
    const VoxelWorld world = terrainWithBlocks({48, 40, 48}, 5, 300);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0), signedUnit(-1.0, 1.0);
    std::uniform_int_distribution<int> cell(0, 47), height(0, 39), face(0, 5);
    // Overhead (two axes straddled by the disk), grazing, along an axis plane, random.
    std::vector<Vec3d> suns = {{0, 1, 0}, normalised({1, 0.02, 0.3}), normalised({0, 1, 1})};
    for (int i = 0; i < 5; ++i) {
        suns.push_back(normalised({signedUnit(rng), 0.05 + unit(rng), signedUnit(rng)}));
    }
    int proofs = 0, openWalks = 0, blockedProofs = 0, blockedWalks = 0;
    for (const Vec3d& s : suns) {
        for (const double radius : {0.0, 0.0047, 0.035, 0.3}) {
            const SunDisk sun = SunDisk::make({float(s.x), float(s.y), float(s.z)}, radius);
            const std::vector<Vec3d> directions = spiralDirections(sun, {8});
            const SunRayMap map = SunRayMap::build(world, directions, true);
            for (int k = 0; k < 3000; ++k) {
                // Half the faces where a ray from above meets the terrain, half any face of any
                // solid voxel (the world's outer faces and faces between two solids too).
                Int3 voxel{cell(rng), height(rng), cell(rng)}, normal{};
                normal[face(rng) / 2] = face(rng) % 2 ? -1 : 1;
                if (k % 2 == 0) {
                    const Hit met = hitFromAbove(world, rng);
                    if (!met.hit || met.normal == Int3{}) continue;
                    voxel = met.voxel, normal = met.normal;
                }
                if (!world.solid(voxel.x, voxel.y, voxel.z) || normal == Int3{}) continue;
                // Anywhere on the face; a third of the points on an edge or a corner.
                const auto across = [&] {
                    return unit(rng) < 0.35 ? double(int(unit(rng) * 2.0)) : unit(rng);
                };
                const Hit hit = faceHit(voxel, normal, across(), across());
                const bool clearStart = map.startsClear(world, hit);
                int lazyClear = -1;  // the hit's start cells, found by the first proof needing them
                for (const Vec3d& l : directions) {
                    // The start cells asked for only where an open ray's proof needs them: the
                    // same answer as with them found first.
                    const SunRayProof lazy = map.prove(world, hit, l, lazyClear);
                    ASSERT_EQ(lazy, map.prove(hit, l, clearStart));
                    if (lazyClear >= 0) {
                        ASSERT_EQ(lazyClear == 1, clearStart);
                    }
                    const bool walkedOpen = !occluded(world, {hit.point, l});
                    openWalks += walkedOpen;
                    blockedWalks += !walkedOpen;
                    if (map.rayBlocked(hit, l)) {
                        ++blockedProofs;
                        ASSERT_FALSE(walkedOpen)
                            << "blocked: sun " << s.x << " " << s.y << " " << s.z << ", radius "
                            << radius << ", point " << hit.point.x << " " << hit.point.y << " "
                            << hit.point.z;
                    }
                    if (!map.open(world, hit, l)) continue;
                    ++proofs;
                    ASSERT_TRUE(walkedOpen)
                        << "sun " << s.x << " " << s.y << " " << s.z << ", radius " << radius
                        << ", voxel " << voxel.x << " " << voxel.y << " " << voxel.z << ", normal "
                        << normal.x << " " << normal.y << " " << normal.z << ", point "
                        << hit.point.x << " " << hit.point.y << " " << hit.point.z;
                }
            }
        }
    }
    // Most open rays proven: the map is not vacuous.
    EXPECT_GT(proofs, openWalks / 2);
    EXPECT_GT(proofs, 30000);
    EXPECT_GT(blockedProofs, blockedWalks / 2);
}

TEST(SunRayMap, ProvesTheLitFloorAndNothingInTheShadow) {
    VoxelWorld world = VoxelWorld::create({40, 16, 40}, 8).value();
    for (int x = 0; x < 40; ++x) {
        for (int z = 0; z < 40; ++z) world.set(x, 0, z, kStone);
    }
    for (int y = 1; y < 9; ++y) world.set(20, y, 20, kStone);  // a pillar
    world.refreshEmptySpace();
    const Vec3d l = normalised({1, 1, 0});
    const SunRayMap map = SunRayMap::build(world, std::vector<Vec3d>{l}, true);
    int lit = 0, provenLit = 0, provenShadowed = 0;
    for (int x = 0; x < 40; ++x) {
        for (int z = 0; z < 40; ++z) {
            if (x == 20 && z == 20) continue;
            const Hit hit = faceHit({x, 0, z}, {0, 1, 0}, 0.5, 0.5);
            const bool open = !occluded(world, {hit.point, l});
            lit += open;
            provenLit += open && map.open(world, hit, l);
            provenShadowed += !open && map.rayBlocked(hit, l);
            // A ray whose texel the pillar marks needs no start cell to be proven.
            int clear = -1;
            if (map.prove(world, hit, l, clear) == SunRayProof::Blocked) {
                EXPECT_EQ(clear, -1) << x << " " << z;
            }
            if (!open) {
                EXPECT_FALSE(map.open(world, hit, l)) << x << " " << z;
            } else {
                EXPECT_FALSE(map.rayBlocked(hit, l)) << x << " " << z;
            }
        }
    }
    // The shadow runs 8 cells from the pillar's foot; about a cell either side of it is lost
    // to texels and slack.
    EXPECT_EQ(lit, 40 * 40 - 1 - 8);
    EXPECT_GT(provenLit, lit - 3 * 8);
    EXPECT_EQ(provenShadowed, 8);
    // Built without solidsStop, it proves nothing blocked.
    const SunRayMap openOnly = SunRayMap::build(world, std::vector<Vec3d>{l});
    EXPECT_FALSE(openOnly.rayBlocked(faceHit({17, 0, 20}, {0, 1, 0}, 0.5, 0.5), l));
    EXPECT_TRUE(map.rayBlocked(faceHit({17, 0, 20}, {0, 1, 0}, 0.5, 0.5), l));
    // A face under a solid voxel, and a direction not mapped, prove nothing.
    EXPECT_FALSE(map.open(world, faceHit({20, 0, 20}, {0, 1, 0}, 0.5, 0.5), l));
    EXPECT_FALSE(
        map.open(world, faceHit({5, 0, 5}, {0, 1, 0}, 0.5, 0.5), normalised({1, 1, 0.01})));
    EXPECT_TRUE(map.open(world, faceHit({5, 0, 5}, {0, 1, 0}, 0.5, 0.5), l));
}

TEST(SunRayMap, MapsEachDirectionOnce) {
    VoxelWorld world = VoxelWorld::create({8, 8, 8}, 8).value();
    world.set(1, 1, 1, kStone);
    const SunDisk delta = SunDisk::make({0.3f, 1.0f, 0.2f}, 0.0);
    const std::vector<Vec3d> same(5, delta.axis);
    EXPECT_EQ(SunRayMap::build(world, same).directions(), 1);
    const SunDisk disk = SunDisk::make({0.3f, 1.0f, 0.2f}, 0.05);
    EXPECT_EQ(SunRayMap::build(world, spiralDirections(disk, {40})).directions(),
              SunRayMap::kMaxDirections);
    EXPECT_FALSE(SunRayMap().open(world, faceHit({1, 1, 1}, {0, 1, 0}, 0.5, 0.5), delta.axis));
}

TEST(SunRayMap, LeavesTheSunsLightAtASurfaceAsItWasToTheBit) {
    VoxelWorld world = terrainWithBlocks({40, 32, 40}, 9, 300);
    // Glass in the sky (texture slot 0): with refraction on, rays through it are dimmed.
    constexpr Voxel kGlass{255, 255, 255, 1};
    for (int x = 10; x < 30; ++x) {
        for (int z = 10; z < 30; ++z) world.set(x, 30, z, kGlass);
    }
    world.refreshEmptySpace();
    for (const bool refraction : {true, false}) {
        ShadeOptions shading;
        shading.sunDirection = {0.4f, 1.0f, -0.3f};
        shading.sunAngularRadius = 0.03;
        shading.refraction = refraction;
        Material glass;
        glass.transmission = 1.0f;
        glass.roughness = 0.0f;
        ASSERT_TRUE(shading.materials.setSlot(0, glass).ok());
        ASSERT_EQ(sunRaysStopAtSolids(nullptr, shading), !refraction);
        // Built to prove blocked rays even where glass lets light through: the sun's light
        // must not take those proofs then.
        const SunDisk sun = SunDisk::make(shading.sunDirection, shading.sunAngularRadius);
        const SunRayMap map = SunRayMap::build(world, spiralDirections(sun, {kSunDiskRays}), true);
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int lit = 0, shadowed = 0;
        for (int k = 0; k < 3000; ++k) {
            const Ray probe{{unit(rng) * 40.0, 31.9, unit(rng) * 40.0},
                            normalised({unit(rng) - 0.5, -1.0, unit(rng) - 0.5})};
            const Hit hit = castRay(world, probe);
            if (!hit.hit || hit.normal == Int3{}) continue;
            const Rgb diffuse(0.6f, 0.5f, 0.4f);
            const Rgb walked = solverSunLobes(world, nullptr, hit, diffuse, nullptr, shading);
            const Rgb proven =
                solverSunLobes(world, nullptr, hit, diffuse, nullptr, shading, kSunDiskRays, &map);
            ASSERT_EQ(walked.r, proven.r) << k;
            ASSERT_EQ(walked.g, proven.g) << k;
            ASSERT_EQ(walked.b, proven.b) << k;
            lit += walked.maxComponent() > 0.0f;
            shadowed += !(walked.maxComponent() > 0.0f);
        }
        EXPECT_GT(lit, 500);
        EXPECT_GT(shadowed, 200);
    }
}

}  // namespace
}  // namespace luxel::voxel
