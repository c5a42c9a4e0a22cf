// The sun as a disk of angular radius r (ShadeOptions::sunAngularRadius) of uniform radiance
// E_sun / (pi sin^2 r), so a face square to it receives E_sun whatever r; r = 0 is a delta
// light. Shared by the path tracer (random directions in the cone, next event estimation), the
// sky visibility renderer and the voxel radiance cascades (a fixed spiral of directions), so all
// three cast the same penumbrae (docs/algorithms/voxel-path-tracing.md).
#pragma once

#include <initializer_list>
#include <vector>

#include "luxel/core/vec.h"

namespace luxel::voxel {

// Orthonormal tangents t, b of a unit vector n (the disk's frame, and the sun rays' maps' planes).
void tangents(Vec3d n, Vec3d& t, Vec3d& b);

struct SunDisk {
    Vec3d axis;                // unit, towards the sun's centre
    double radius = 0.0;       // angular radius in radians; 0: a delta light
    double oneMinusCos = 0.0;  // 1 - cos r, computed as 2 sin^2(r / 2) (no cancellation)
    double cosRadius = 1.0;

    static SunDisk make(Vec3 direction, double angularRadius);
    bool delta() const { return !(oneMinusCos > 0.0); }
    // Whether a unit direction lies inside the disk (never for a delta sun).
    bool contains(Vec3d direction) const;
    // Density of uniform directions in the cone, 1 / (2 pi (1 - cos r)), per steradian.
    double pdf() const;
    // The disk's radiance for irradiance `irradiance` on a face square to the sun.
    Rgb radiance(Rgb irradiance) const;
    // radiance / pdf = irradiance * 2 / (1 + cos r): what one uniform sample of the cone brings.
    Rgb radianceOverPdf(Rgb irradiance) const;
    // A direction uniform in solid angle over the cone from two numbers in [0, 1): u0 picks the
    // angle from the axis (1 - cos theta = u0 (1 - cos r)), u1 the azimuth. The axis itself for
    // a delta sun.
    Vec3d sample(float u0, float u1) const;
    // Direction i of a fixed spiral of `count` directions spread evenly over the cone (Vogel's
    // golden-angle spiral): the same for every caller, so deterministic soft shadows agree.
    Vec3d spiral(int i, int count) const;
    // The orthonormal tangents sample() turns about the axis (the GPU tracer's cone uses them).
    void frame(Vec3d& t, Vec3d& b) const;
};

// The directions of the disk's spirals of each of `counts` rays, one after another (a delta sun:
// its axis once for each): the rays the real-time solvers cast, for SunRayMap to map.
std::vector<Vec3d> spiralDirections(const SunDisk& sun, std::initializer_list<int> counts);

// The disk as the GPU passes' push constants carry it (the path tracer's, the cascades'
// picture's: the same named fields), computed in double and rounded once: 1 - cos r, the
// radiance per unit irradiance and the frame's tangents; left zero for a delta sun.
template <typename Push>
void packSunDisk(const SunDisk& disk, Push& p) {
    if (disk.delta()) return;
    Vec3d t, b;
    disk.frame(t, b);
    p.sunOneMinusCos = float(disk.oneMinusCos);
    p.sunRadianceScale = disk.radiance(Rgb(1.0f)).r;  // 1 / (pi sin^2 r)
    p.sunTangentX = float(t.x), p.sunTangentY = float(t.y), p.sunTangentZ = float(t.z);
    p.sunBitangentX = float(b.x), p.sunBitangentY = float(b.y), p.sunBitangentZ = float(b.z);
}

}  // namespace luxel::voxel
