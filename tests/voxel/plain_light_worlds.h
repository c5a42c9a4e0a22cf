// Worlds and light for the voxel global illumination tests (the path tracer, the radiance
// cascades): plain diffuse blocks lit only by what a test sets, and an open floor.
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include "luxel/voxel/material.h"
#include "luxel/voxel/shading.h"
#include "luxel/voxel/voxel_world.h"
#include "voxel/path_trace_bsdf.h"

namespace luxel::voxel::test {

inline constexpr Voxel kWhite{255, 255, 255, 255};

inline VoxelWorld makeWorld(Int3 size) {
    auto world = VoxelWorld::create(size, 8);
    EXPECT_TRUE(world.ok());
    return std::move(*world);
}

// A 20 x 8 x 20 floor with a glass slab two voxels thick lying on part of it and a glass block
// standing on it; the glass is texture slot 0.
inline VoxelWorld floorWithGlass() {
    constexpr Voxel kGlass{255, 255, 255, 1};
    VoxelWorld world = makeWorld({20, 8, 20});
    for (int z = 0; z < 20; ++z)
        for (int x = 0; x < 20; ++x) world.set(x, 0, z, kWhite);
    for (int z = 3; z < 11; ++z)
        for (int x = 3; x < 11; ++x) world.set(x, 1, z, kGlass), world.set(x, 2, z, kGlass);
    for (int y = 1; y < 4; ++y)
        for (int z = 13; z < 16; ++z)
            for (int x = 12; x < 15; ++x) world.set(x, y, z, kGlass);
    world.refreshEmptySpace();
    return world;
}

// Light only from the materials and the sky the test sets; plain diffuse blocks: Lambertian in
// the path tracer too (ior 1: no index contrast, so no specular layer), and a delta sun unless
// a test gives it a radius.
inline ShadeOptions plainLight(float albedo, Rgb emission, Rgb sky) {
    ShadeOptions o;
    o.textures = false;
    o.sunIrradiance = Rgb(0.0f);
    o.sunAngularRadius = 0.0;
    o.skyTop = o.skyHorizon = sky;
    Material m;
    m.name = "test";
    m.albedo = Rgb(albedo);
    m.emission = emission;
    m.ior = 1.0f;
    EXPECT_TRUE(o.materials.setPlain(m).ok());
    return o;
}

// A one-voxel floor (y = 0) in a world two voxels high: every ray leaving the floor upwards sees
// the sky at once, as from an infinite plane.
inline VoxelWorld floorWorld() {
    VoxelWorld world = makeWorld({32, 2, 32});
    for (int z = 0; z < 32; ++z)
        for (int x = 0; x < 32; ++x) world.set(x, 0, z, kWhite);
    world.refreshEmptySpace();
    return world;
}

// Clear glass (ior 1.5, smooth, fully transmissive) absorbing `absorption` per voxel inside.
inline Material glass(Rgb absorption = Rgb(0.0f)) {
    Material m;
    m.name = "glass";
    m.ior = 1.5f;
    m.roughness = 0.0f;
    m.transmission = 1.0f;
    m.absorption = absorption;
    return m;
}

inline Material metal(float roughness, Rgb albedo) {
    Material m;
    m.name = "metal";
    m.metallic = 1.0f;
    m.roughness = roughness;
    m.albedo = albedo;
    return m;
}

// A polished dielectric floor (ior 1.5, roughness 0.4: a GGX lobe narrow enough to show a lamp's
// reflection) of diffuse albedo `albedo`.
inline Material polishedFloor(float albedo) {
    Material m;
    m.name = "polished floor";
    m.albedo = Rgb(albedo);
    m.roughness = 0.4f;
    m.ior = 1.5f;
    return m;
}

// A glowing voxel's material: emission only, the default albedo.
inline Material lampMaterial(Rgb emission) {
    Material m;
    m.name = "lamp";
    m.emission = emission;
    return m;
}

// A closed 14-voxel room of kWhite walls one voxel thick, in plainLight(albedo) with no sky,
// and one lamp voxel (texture slot 0, lampMaterial(radiance)) at `lamp`.
struct ClosedLampRoom {
    VoxelWorld world = makeWorld({14, 14, 14});
    ShadeOptions o;
    ClosedLampRoom(Int3 lamp, float albedo, Rgb radiance)
        : o(plainLight(albedo, Rgb(0.0f), Rgb(0.0f))) {
        for (int z = 0; z < 14; ++z)
            for (int y = 0; y < 14; ++y)
                for (int x = 0; x < 14; ++x) {
                    if (x == 0 || y == 0 || z == 0 || x == 13 || y == 13 || z == 13) {
                        world.set(x, y, z, kWhite);
                    }
                }
        world.set(lamp.x, lamp.y, lamp.z, Voxel{255, 255, 255, 1});
        world.refreshEmptySpace();
        EXPECT_TRUE(o.materials.setSlot(0, lampMaterial(radiance)).ok());
    }
};

// An 8x8x16 world with a wall at z = 0 (texture slot 1) seen through a slab three voxels thick
// across the whole cross-section (z = 6..8, texture slot 0): the Fresnel-series glass tests.
inline VoxelWorld slabBeforeAWall() {
    VoxelWorld world = makeWorld({8, 8, 16});
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            world.set(x, y, 0, Voxel{255, 255, 255, 2});
            for (int z = 6; z < 9; ++z) world.set(x, y, z, Voxel{255, 255, 255, 1});
        }
    world.refreshEmptySpace();
    return world;
}

// A white floor (y = 0) under a pane one voxel thick (y = 5, texture slot 0) that covers the
// whole 24x8x24 world: the sun-through-glass tests.
inline VoxelWorld paneOverAFloor() {
    VoxelWorld world = makeWorld({24, 8, 24});
    for (int z = 0; z < 24; ++z)
        for (int x = 0; x < 24; ++x) {
            world.set(x, 0, z, kWhite);
            world.set(x, 5, z, Voxel{255, 255, 255, 1});
        }
    world.refreshEmptySpace();
    return world;
}

// A GGX-only lobe of reflectance 1 on a floor (normal +y) seen at cosView, as the GGX
// directional-albedo table integrates it.
inline PathBsdf ggxOnlyLobe(double cosView, double alpha) {
    PathBsdf b;
    b.normal = {0, 1, 0};
    b.view = {std::sqrt(1.0 - cosView * cosView), cosView, 0.0};
    b.cosView = cosView;
    b.alpha = float(alpha);
    b.specular = Rgb(1.0f);
    b.pSpecular = 1.0;
    return b;
}

}  // namespace luxel::voxel::test
