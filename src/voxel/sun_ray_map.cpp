// Sun rays proven open or blocked (sun_ray_map.h).
#include "sun_ray_map.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "face_normal.h"
#include "luxel/core/parallel.h"
#include "sun_disk.h"

namespace luxel::voxel {
namespace {

constexpr std::int16_t kNothing = std::numeric_limits<std::int16_t>::min();
// Slack for rounding, far above the walk's own (float or double: a cell it enters lies within
// about 1e-5 voxels of the exact ray in worlds of thousands): around a voxel's projection and
// around a start point's cell boundaries, in voxels.
constexpr double kProjectionSlack = 1e-3;
constexpr double kStartSlack = 1e-4;
// A direction leaves a face plane when its component along the normal is above this.
constexpr double kLeaves = 1e-9;

bool sameBits(const Vec3d& a, const Vec3d& b) {
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
           std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

// Whether solid voxel (x, y, z) has a non-solid face neighbour (outside the world counts): the
// first solid cell a walk from an empty cell enters is one.
bool exposed(const VoxelWorld& world, int x, int y, int z) {
    return !world.solid(x - 1, y, z) || !world.solid(x + 1, y, z) || !world.solid(x, y - 1, z) ||
           !world.solid(x, y + 1, z) || !world.solid(x, y, z - 1) || !world.solid(x, y, z + 1);
}

// The unit cube's silhouette along a direction: the convex hull of its corners' projections,
// as half-planes n . q >= c that hold a point q (relative to the voxel's own projection) inside
// it by at least kProjectionSlack.
struct Silhouette {
    std::vector<std::array<double, 3>> halfPlanes;  // nu, nv, c
    bool holds(double u, double v) const {
        for (const auto& h : halfPlanes) {
            if (!(h[0] * u + h[1] * v >= h[2])) return false;
        }
        return true;
    }
};

Silhouette silhouetteOf(const Vec3d& tu, const Vec3d& tv) {
    std::vector<std::array<double, 2>> p;
    for (int c = 0; c < 8; ++c) {
        const Vec3d corner{double(c & 1), double(c >> 1 & 1), double(c >> 2 & 1)};
        p.push_back({dot(corner, tu), dot(corner, tv)});
    }
    std::sort(p.begin(), p.end());
    const auto turn = [](const std::array<double, 2>& o, const std::array<double, 2>& a,
                         const std::array<double, 2>& b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    };
    // Andrew's monotone chain: the hull counter-clockwise, collinear points dropped.
    std::vector<std::array<double, 2>> hull(16);
    int k = 0;
    for (int i = 0; i < 8; ++i) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], p[i]) <= 1e-12) --k;
        hull[k++] = p[i];
    }
    for (int i = 6, lower = k + 1; i >= 0; --i) {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], p[i]) <= 1e-12) --k;
        hull[k++] = p[i];
    }
    Silhouette s;
    for (int i = 0; i + 1 < k; ++i) {
        // Inward normal of edge a -> b on a counter-clockwise hull: (-(b - a).v, (b - a).u).
        const double eu = hull[i + 1][0] - hull[i][0], ev = hull[i + 1][1] - hull[i][1];
        const double length = std::sqrt(eu * eu + ev * ev);
        if (!(length > 1e-12)) continue;
        const double nu = -ev / length, nv = eu / length;
        s.halfPlanes.push_back({nu, nv, nu * hull[i][0] + nv * hull[i][1] + kProjectionSlack});
    }
    return s;
}

}  // namespace

SunRayMap::View SunRayMap::mapOne(Int3 size, Vec3d direction,
                                  const std::vector<Int3>& exposedVoxels, bool solidsStop) {
    View view;
    view.direction = direction;
    bool any = false;
    for (int n = 0; n < 6; ++n) {
        view.on[std::size_t(n)] = (n % 2 ? -1.0 : 1.0) * direction[n / 2] > kLeaves;
        any = any || view.on[std::size_t(n)];
    }
    if (!any || exposedVoxels.empty()) return view;
    tangents(direction, view.tangentU, view.tangentV);
    const Vec3d &tu = view.tangentU, &tv = view.tangentV;
    // The unit cube's projection: its corners' least and largest offsets from the voxel's.
    double cubeLoU = 0, cubeHiU = 0, cubeLoV = 0, cubeHiV = 0;
    // The projection of the world's box, a texel to spare around it.
    double minU = 0, maxU = 0, minV = 0, maxV = 0;
    for (int a = 0; a < 3; ++a) {
        cubeLoU += std::min(0.0, tu[a]), cubeHiU += std::max(0.0, tu[a]);
        cubeLoV += std::min(0.0, tv[a]), cubeHiV += std::max(0.0, tv[a]);
        minU += std::min(0.0, tu[a] * size[a]), maxU += std::max(0.0, tu[a] * size[a]);
        minV += std::min(0.0, tv[a] * size[a]), maxV += std::max(0.0, tv[a] * size[a]);
    }
    view.texel = std::max(0.25, std::max(maxU - minU, maxV - minV) / (kMaxTexelsPerSide - 4));
    view.perTexel = 1.0 / view.texel;
    view.originU = minU - 2.0 * view.texel, view.originV = minV - 2.0 * view.texel;
    view.sizeU = int(std::ceil((maxU - minU) / view.texel)) + 4;
    view.sizeV = int(std::ceil((maxV - minV) / view.texel)) + 4;
    const std::size_t texels = std::size_t(view.sizeU) * std::size_t(view.sizeV);
    for (int n = 0; n < 6; ++n) {
        if (view.on[std::size_t(n)]) view.key[std::size_t(n)].assign(texels, kNothing);
    }
    const Silhouette silhouette = silhouetteOf(tu, tv);
    double cubeLeastDepth = 0.0;
    for (int a = 0; a < 3; ++a) cubeLeastDepth += std::min(0.0, direction[a]);
    if (solidsStop) view.ahead.assign(texels, -std::numeric_limits<float>::infinity());
    // Every exposed solid voxel marks the texels its projection touches (with slack).
    const double inv = view.perTexel;
    for (const Int3& e : exposedVoxels) {
        const int x = e.x, y = e.y, z = e.z;
        const Vec3d corner{double(x), double(y), double(z)};
        const double u = dot(corner, tu) - view.originU;
        const double v = dot(corner, tv) - view.originV;
        const int u0 = int(std::floor((u + cubeLoU - kProjectionSlack) * inv));
        const int u1 = int(std::floor((u + cubeHiU + kProjectionSlack) * inv));
        const int v0 = int(std::floor((v + cubeLoV - kProjectionSlack) * inv));
        const int v1 = int(std::floor((v + cubeHiV + kProjectionSlack) * inv));
        const int coordinate[3] = {x, y, z};
        for (int n = 0; n < 6; ++n) {
            if (!view.on[std::size_t(n)]) continue;
            const auto key = std::int16_t(n % 2 ? -coordinate[n / 2] : coordinate[n / 2]);
            std::vector<std::int16_t>& keys = view.key[std::size_t(n)];
            for (int j = v0; j <= v1; ++j) {
                std::int16_t* row = keys.data() + std::size_t(j) * std::size_t(view.sizeU);
                for (int i = u0; i <= u1; ++i) row[i] = std::max(row[i], key);
            }
        }
        if (view.ahead.empty()) continue;
        // The texels wholly inside the silhouette (corners with slack): a line through
        // any point of them passes through the voxel's inside.
        const auto depth = float(dot(corner, direction) + cubeLeastDepth);
        for (int j = v0; j <= v1; ++j) {
            const double lo = j * view.texel - v, hi = lo + view.texel;
            for (int i = u0; i <= u1; ++i) {
                const double left = i * view.texel - u, right = left + view.texel;
                if (!silhouette.holds(left, lo) || !silhouette.holds(right, lo) ||
                    !silhouette.holds(left, hi) || !silhouette.holds(right, hi)) {
                    continue;
                }
                float& a = view.ahead[std::size_t(j) * std::size_t(view.sizeU) + i];
                a = std::max(a, depth);
            }
        }
    }
    return view;
}

SunRayMap SunRayMap::build(const VoxelWorld& world, std::span<const Vec3d> directions,
                           bool solidsStop) {
    // The solid voxels with a non-solid neighbour: only they mark.
    const Int3 size = world.size();
    std::vector<Int3> exposedVoxels;
    for (int z = 0; z < size.z; ++z) {
        for (int y = 0; y < size.y; ++y) {
            for (int x = 0; x < size.x; ++x) {
                if (world.solid(x, y, z) && exposed(world, x, y, z))
                    exposedVoxels.push_back({x, y, z});
            }
        }
    }
    std::vector<Vec3d> unique;
    for (const Vec3d& d : directions) {
        if (int(unique.size()) == kMaxDirections) break;
        if (!(std::abs(dot(d, d) - 1.0) < 1e-9)) continue;
        const bool mapped = std::any_of(unique.begin(), unique.end(),
                                        [&](const Vec3d& u) { return sameBits(u, d); });
        if (!mapped) unique.push_back(d);
    }
    SunRayMap map;
    map.views_.resize(unique.size());
    parallelForRange(int(unique.size()), 1, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            map.views_[std::size_t(i)] =
                mapOne(size, unique[std::size_t(i)], exposedVoxels, solidsStop);
        }
    });
    return map;
}

bool SunRayMap::startsClear(const VoxelWorld& world, const Hit& hit) const {
    if (views_.empty() || !hit.hit || hit.normal == Int3{}) return false;
    const int n = normalIndex(hit.normal), axis = n / 2;
    const bool positive = n % 2 == 0;
    const int plane = positive ? hit.voxel[axis] + 1 : hit.voxel[axis];
    if (!(hit.point[axis] == double(plane))) return false;
    // The cell in front of the face, and on (or near, for a walk in float) a cell boundary
    // across the face those either side: castRay's start-cell rule picks by the ray's sign. All
    // inside the world, so the ray starts inside it (a start on the world's boundary is entered
    // through the world's face, with its cell clamped into the world).
    Int3 lo, hi;
    for (int a = 0; a < 3; ++a) {
        if (a == axis) {
            lo[a] = hi[a] = positive ? plane : plane - 1;
            continue;
        }
        lo[a] = int(std::floor(hit.point[a] - kStartSlack));
        hi[a] = int(std::floor(hit.point[a] + kStartSlack));
    }
    for (int z = lo.z; z <= hi.z; ++z) {
        for (int y = lo.y; y <= hi.y; ++y) {
            for (int x = lo.x; x <= hi.x; ++x) {
                if (!world.inside(x, y, z) || world.solid(x, y, z)) return false;
            }
        }
    }
    return true;
}

const SunRayMap::View* SunRayMap::viewOf(const Vec3d& direction) const {
    for (const View& view : views_) {
        if (sameBits(view.direction, direction)) return &view;
    }
    return nullptr;
}

namespace {

// The texel of point p in a view, or -1 outside it (a point within rounding of a texel's edge may
// fall either side: the marks' slack covers both).
template <typename View>
std::int64_t texelOf(const View& view, const Vec3d& p) {
    const double i = std::floor((dot(p, view.tangentU) - view.originU) * view.perTexel);
    const double j = std::floor((dot(p, view.tangentV) - view.originV) * view.perTexel);
    if (!(i >= 0.0 && j >= 0.0 && i < double(view.sizeU) && j < double(view.sizeV))) return -1;
    return std::int64_t(j) * view.sizeU + std::int64_t(i);
}

// Depth a voxel must lie ahead of a point by (float depths of worlds of thousands of voxels
// round by under 3e-4).
constexpr double kAheadSlack = 1e-2;

}  // namespace

namespace {

// SunRayMap::prove's answer, with `startsClear()` asked only where the open ray's proof needs it.
template <typename View, typename StartsClear>
SunRayProof proveIn(const View* view, const Hit& hit, const Vec3d& direction,
                    StartsClear startsClear) {
    if (!view) return SunRayProof::None;
    const std::int64_t texel = texelOf(*view, hit.point);
    if (texel < 0) return SunRayProof::None;
    const int n = normalIndex(hit.normal), axis = n / 2;
    if (view->on[std::size_t(n)]) {
        // The voxels beyond the face's plane, which the ray may enter.
        const int plane = n % 2 == 0 ? hit.voxel[axis] + 1 : hit.voxel[axis];
        const int threshold = n % 2 == 0 ? plane : 1 - plane;
        if (int(view->key[std::size_t(n)][std::size_t(texel)]) < threshold && startsClear()) {
            return SunRayProof::Open;
        }
    }
    if (!view->ahead.empty() &&
        double(view->ahead[std::size_t(texel)]) >= dot(hit.point, direction) + kAheadSlack) {
        return SunRayProof::Blocked;
    }
    return SunRayProof::None;
}

}  // namespace

SunRayProof SunRayMap::prove(const Hit& hit, const Vec3d& direction, bool startsClear) const {
    return proveIn(viewOf(direction), hit, direction, [&] { return startsClear; });
}

SunRayProof SunRayMap::prove(const VoxelWorld& world, const Hit& hit, const Vec3d& direction,
                             int& clear) const {
    return proveIn(viewOf(direction), hit, direction, [&] {
        if (clear < 0) clear = startsClear(world, hit) ? 1 : 0;
        return clear == 1;
    });
}

bool SunRayMap::rayOpen(const Hit& hit, const Vec3d& direction) const {
    return prove(hit, direction, true) == SunRayProof::Open;
}

bool SunRayMap::rayBlocked(const Hit& hit, const Vec3d& direction) const {
    return prove(hit, direction, false) == SunRayProof::Blocked;
}

std::uint64_t SunRayMap::bytes() const {
    std::uint64_t total = 0;
    for (const View& v : views_) {
        for (const auto& k : v.key) total += k.size() * sizeof(std::int16_t);
        total += v.ahead.size() * sizeof(float);
    }
    return total;
}

}  // namespace luxel::voxel
