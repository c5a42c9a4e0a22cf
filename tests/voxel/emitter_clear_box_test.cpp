// EmitterClearBox (src/voxel/cascades/emitter_clear_box.h): every near-emitter visibility line it
// proves clear is clear by the walk it replaces (faceRayTransmittance 1, the line aimed as
// NearEmitterRays aims it), from points anywhere on every face near lamps hung among random
// blocks (edges and corners too) and from every pixel of the shipped thin-walls scene; every
// lamp ray it proves meets the voxel of the panel it names first, as castRay finds (panels of
// several voxels, points on their edges too); its boxes hold only empty cells; it proves most of
// thin-walls' near lines; and the picture's near light and highlight are the same to the bit
// with the boxes as without.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "luxel/voxel/render_image.h"
#include "luxel/voxel/surface_cast.h"
#include "luxel/voxel/voxel_scene.h"
#include "voxel/cascade_states.h"
#include "voxel/cascades/cascade_near_rays.h"
#include "voxel/cascades/cascade_state.h"
#include "voxel/cascades/emitter_clear_box.h"
#include "voxel/face_normal.h"
#include "voxel/path_trace_bsdf.h"
#include "voxel/path_trace_surface.h"
#include "voxel/plain_light_worlds.h"
#include "voxel/solver_sun.h"
#include "voxel/terrain_with_blocks.h"

namespace luxel::voxel {
namespace {

using namespace luxel::voxel::cascades;
namespace shared = gpu::shared;

// The walk NearEmitterRays::transmittance casts from `hit` to quarter q of emitter e.
Rgb walkedLine(const VoxelWorld& world, const ShadeOptions& shading, const Hit& hit,
               const shared::CascadeNearEmitter& e, int q) {
    const shared::vec3 p(float(hit.point.x), float(hit.point.y), float(hit.point.z));
    const shared::vec3 d = normalize(shared::nearEmitterPoint(e, q) - p);
    const FaceTarget target{{e.x, e.y, e.z}, normalFromIndex(int(e.normal))};
    return faceRayTransmittance(
        world, nullptr, {hit.point, {double(d.x), double(d.y), double(d.z)}}, shading, target);
}

// A closed cube room `side` cells wide, walls one cell thick, with white blocks in a `fraction`
// of its cells, drawn from `rng`.
VoxelWorld closedRoomWithBlocks(int side, double fraction, std::mt19937& rng) {
    VoxelWorld world = test::makeWorld({side, side, side});
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int z = 0; z < side; ++z)
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                const bool wall =
                    x == 0 || y == 0 || z == 0 || x == side - 1 || y == side - 1 || z == side - 1;
                if (wall || unit(rng) < fraction) world.set(x, y, z, test::kWhite);
            }
    return world;
}

TEST(EmitterClearBox, ProvesOnlyLinesTheWalkFindsClear) {
    // A closed room with random blocks (a fifth of its cells) and lamps among them.
    constexpr int kSide = 16;
    std::mt19937 rng(7);
    VoxelWorld world = closedRoomWithBlocks(kSide, 0.2, rng);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> inner(1, kSide - 2);
    std::vector<Int3> lamps;
    for (int k = 0; k < 12; ++k) {
        const Int3 v{inner(rng), inner(rng), inner(rng)};
        world.set(v.x, v.y, v.z, Voxel{255, 255, 255, 1});
        lamps.push_back(v);
    }
    world.refreshEmptySpace();
    const ShadeOptions shading = test::plainLight(0.5f, Rgb(0.0f), Rgb(0.0f));
    int proofs = 0, boxes = 0;
    const double corners[] = {0.0, 1.0};
    for (const Int3& lamp : lamps) {
        for (int normal = 0; normal < 6; ++normal) {
            const EmitterClearBox box = growEmitterClearBox(world, lamp, normal, 1, 1, 5);
            if (box.empty()) continue;
            ++boxes;
            for (int z = box.lo.z; z < box.hi.z; ++z)
                for (int y = box.lo.y; y < box.hi.y; ++y)
                    for (int x = box.lo.x; x < box.hi.x; ++x) ASSERT_FALSE(world.solid(x, y, z));
            const shared::CascadeNearEmitter e{lamp.x, lamp.y, lamp.z, std::uint32_t(normal),
                                               1.0f,   1.0f,   1.0f,   0};
            // Every face of every solid voxel around the box, at its centre, its corners and
            // random points; the lamp's own faces too.
            for (int z = box.lo.z - 1; z <= box.hi.z; ++z)
                for (int y = box.lo.y - 1; y <= box.hi.y; ++y)
                    for (int x = box.lo.x - 1; x <= box.hi.x; ++x) {
                        if (!world.solid(x, y, z)) continue;
                        for (int f = 0; f < 6; ++f) {
                            const Int3 n = normalFromIndex(f);
                            std::vector<std::pair<double, double>> at = {{0.5, 0.5}};
                            for (double a : corners)
                                for (double b : corners) at.emplace_back(a, b);
                            for (int r = 0; r < 4; ++r) at.emplace_back(unit(rng), unit(rng));
                            for (const auto& [a, b] : at) {
                                const Hit hit = faceHit({x, y, z}, n, a, b);
                                if (!lineProvenClear(box, hit)) continue;
                                ++proofs;
                                for (int q = 0; q < 4; ++q) {
                                    const Rgb t = walkedLine(world, shading, hit, e, q);
                                    ASSERT_EQ(t.r, 1.0f)
                                        << "lamp face " << normal << " from " << x << "," << y
                                        << "," << z << " face " << f << " at " << a << "," << b;
                                    ASSERT_EQ(t.g, 1.0f);
                                    ASSERT_EQ(t.b, 1.0f);
                                }
                            }
                        }
                    }
        }
    }
    EXPECT_GT(boxes, 20);
    EXPECT_GT(proofs, 500);
}

TEST(EmitterClearBox, ProvesOnlyLampRaysTheWalkSendsToTheirVoxel) {
    // Panels of 1x1 up to 3x2 voxels among random blocks in a closed room; rays from the faces
    // around each panel's box to uniform points of the panel (its edges and corners too).
    constexpr int kSide = 20;
    std::mt19937 rng(11);
    VoxelWorld world = closedRoomWithBlocks(kSide, 0.05, rng);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> inner(1, kSide - 4), size(1, 3), side(0, 5);
    struct Panel {
        Int3 corner;
        int normal, sizeA, sizeB;
    };
    std::vector<Panel> panels;
    for (int k = 0; k < 32; ++k) {
        Panel p{{inner(rng), inner(rng), inner(rng)}, side(rng), size(rng), size(rng)};
        const int axis = p.normal / 2;
        for (int b = 0; b < p.sizeB; ++b)
            for (int a = 0; a < p.sizeA; ++a) {
                Int3 v = p.corner;
                v[(axis + 1) % 3] += a;
                v[(axis + 2) % 3] += b;
                world.set(v.x, v.y, v.z, Voxel{255, 255, 255, 1});
            }
        panels.push_back(p);
    }
    world.refreshEmptySpace();
    int proofs = 0;
    for (const Panel& panel : panels) {
        const EmitterClearBox box =
            growEmitterClearBox(world, panel.corner, panel.normal, panel.sizeA, panel.sizeB, 16);
        if (box.empty()) continue;
        const int axis = panel.normal / 2, a = (axis + 1) % 3, b = (axis + 2) % 3;
        const Int3 outward = normalFromIndex(panel.normal);
        const double plane = double(box.emitterPlane);
        for (int z = box.lo.z - 1; z <= box.hi.z; ++z)
            for (int y = box.lo.y - 1; y <= box.hi.y; ++y)
                for (int x = box.lo.x - 1; x <= box.hi.x; ++x) {
                    if (!world.solid(x, y, z)) continue;
                    for (int f = 0; f < 6; ++f) {
                        for (int r = 0; r < 32; ++r) {
                            const double fa = r < 2 ? double(r) : unit(rng);
                            const Hit hit = faceHit({x, y, z}, normalFromIndex(f), fa, unit(rng));
                            // A point of the panel, its edges and corners included, aimed at in
                            // float as the light samples aim.
                            Vec3d target;
                            target[axis] = plane;
                            target[a] = panel.corner[a] + panel.sizeA * (r == 2 ? 0.0 : unit(rng));
                            target[b] = panel.corner[b] + panel.sizeB * (r == 3 ? 1.0 : unit(rng));
                            const shared::vec3 l = normalize(
                                shared::vec3(float(target.x), float(target.y), float(target.z)) -
                                shared::vec3(float(hit.point.x), float(hit.point.y),
                                             float(hit.point.z)));
                            const Ray ray{hit.point, {double(l.x), double(l.y), double(l.z)}};
                            const double reach = (plane - hit.point[axis]) / ray.direction[axis];
                            Int3 voxel;
                            if (!rayProvenToRect(box, hit, ray.direction, reach, &voxel)) continue;
                            ++proofs;
                            const Hit seen = castRay(world, ray);
                            ASSERT_TRUE(seen.hit);
                            ASSERT_EQ(seen.normal, outward);
                            ASSERT_EQ(seen.voxel, voxel)
                                << "panel at " << panel.corner.x << "," << panel.corner.y << ","
                                << panel.corner.z << " from " << x << "," << y << "," << z;
                        }
                    }
                }
    }
    EXPECT_GT(proofs, 5000);
}

TEST(EmitterClearBox, ProvesMostNearLinesOfThinWallsAndChangesNoBit) {
    auto scene =
        loadVoxelScene(std::string(LUXEL_SOURCE_DIR) + "/scenes/voxel/thin-walls.json", 160, 90);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const auto state = test::buildCascadeState(scene->world, &scene->textures, scene->shading);
    const FaceData& faces = state->faces;
    ASSERT_EQ(faces.nearBox.size(), faces.nearEmitters.size());
    ASSERT_FALSE(faces.nearEmitters.empty());
    // The same state without the boxes: every line walked.
    auto walked = test::buildCascadeState(scene->world, &scene->textures, scene->shading);
    walked->faces.nearBox.clear();
    const ShadeOptions& shading = state->shading;
    long proven = 0, lines = 0;
    for (int y = 0; y < scene->camera.height(); ++y) {
        for (int x = 0; x < scene->camera.width(); ++x) {
            const Ray ray = pixelSampleRay(scene->camera, x, y, 0, 1);
            const SurfaceHit s = castToSurface(*state->world, state->textures, ray, 0);
            if (!s.hit.hit || s.hit.normal == Int3{}) continue;
            const int face = faces.table.find(s.hit.voxel, normalIndex(s.hit.normal));
            if (face < 0) continue;
            for (std::uint32_t i = faces.nearOffset[face]; i < faces.nearOffset[face + 1]; ++i) {
                lines += 4;
                if (!lineProvenClear(faces.nearBoxes[faces.nearBox[i]], s.hit)) continue;
                proven += 4;
                for (int q = 0; q < 4; ++q) {
                    const Rgb t =
                        walkedLine(*state->world, shading, s.hit, faces.nearEmitters[i], q);
                    ASSERT_TRUE(t.r == 1.0f && t.g == 1.0f && t.b == 1.0f)
                        << "pixel " << x << "," << y << " emitter " << i << " quarter " << q;
                }
            }
            // The near light and highlight with the boxes and without, to the bit.
            const PathSurface surface = pathSurfaceAt(*state->world, s, shading);
            const PathBsdf specular =
                specularLobe(pathBsdf(*surface.material, surface.albedo, s.hit.normal,
                                      normalize(ray.direction), shading));
            const Rgb light = nearEmitterLight(*state, s.hit);
            const Rgb highlight = nearEmitterHighlight(*state, s.hit, specular);
            const Rgb light0 = nearEmitterLight(*walked, s.hit);
            const Rgb highlight0 = nearEmitterHighlight(*walked, s.hit, specular);
            for (int c = 0; c < 3; ++c) {
                ASSERT_EQ(light[c], light0[c]) << "pixel " << x << "," << y;
                ASSERT_EQ(highlight[c], highlight0[c]) << "pixel " << x << "," << y;
            }
        }
    }
    EXPECT_GT(lines, 1000);
    // The lamp stands in an empty corner of its room: most of its lines are proven.
    EXPECT_GT(proven, lines / 2);
}

}  // namespace
}  // namespace luxel::voxel
