// Exact Euclidean distance transform and the signed voxel distance field.
//
// Based on: Felzenszwalb & Huttenlocher, "Distance Transforms of Sampled Functions", Theory of
// Computing 8:415-428, 2012. The squared distance is separable: a 1-D transform (the lower
// envelope of the parabolas (q - p)^2 + f(p)) along x, then y, then z; O(n) per line.
#include "luxel/voxel/shadows/distance_field.h"

#include <algorithm>
#include <cmath>

#include "gpu/shaders/shared/soft_shadow.h"
#include "luxel/core/parallel.h"

namespace luxel::voxel {
static_assert(DistanceField::kCap == LUXEL_SDF_FIELD_CAP);

namespace {

// D[q] = min_p (q - p)^2 + f[p] for one line (Felzenszwalb & Huttenlocher 2012, Algorithm 1),
// and arg[q], the minimizing p. v, z: scratch of n and n + 1 entries.
void transformLine(const double* f, double* d, int* arg, int n, int* v, double* z) {
    int k = 0;
    v[0] = 0;
    z[0] = -kEdtInfinity;
    z[1] = kEdtInfinity;
    for (int q = 1; q < n; ++q) {
        double s;
        for (;;) {
            const int p = v[k];
            s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * q - 2.0 * p);
            if (s > z[k] || k == 0) break;
            --k;
        }
        // With k == 0 and s <= z[0] = -inf impossible; the loop above always ends with s > z[k].
        ++k;
        v[k] = q;
        z[k] = s;
        z[k + 1] = kEdtInfinity;
    }
    k = 0;
    for (int q = 0; q < n; ++q) {
        while (z[k + 1] < q) ++k;
        const double dq = double(q - v[k]);
        d[q] = dq * dq + f[v[k]];
        arg[q] = v[k];
    }
}

// One axis of the separable transform, in place, lines in parallel. `nearest` (when not empty)
// follows the minimizers: the feature a cell's value came from (the feature transform).
void transformAxis(std::vector<double>& grid, std::vector<std::int32_t>& nearest, Int3 size,
                   int axis) {
    const int n = size[axis];
    const int a1 = axis == 0 ? 1 : 0, a2 = axis == 2 ? 1 : 2;
    const std::size_t stride[3] = {1, static_cast<std::size_t>(size.x),
                                   static_cast<std::size_t>(size.x) * size.y};
    const int lines = size[a1] * size[a2];
    parallelForRange(lines, 64, [&](int begin, int end) {
        std::vector<double> f(n), d(n), z(n + 1);
        std::vector<int> v(n), arg(n);
        std::vector<std::int32_t> from(n);
        for (int line = begin; line < end; ++line) {
            const std::size_t base =
                (line % size[a1]) * stride[a1] + (line / size[a1]) * stride[a2];
            for (int q = 0; q < n; ++q) f[q] = grid[base + q * stride[axis]];
            transformLine(f.data(), d.data(), arg.data(), n, v.data(), z.data());
            for (int q = 0; q < n; ++q) grid[base + q * stride[axis]] = d[q];
            if (nearest.empty()) continue;
            for (int q = 0; q < n; ++q) from[q] = nearest[base + q * stride[axis]];
            for (int q = 0; q < n; ++q) nearest[base + q * stride[axis]] = from[arg[q]];
        }
    });
}

}  // namespace

std::vector<double> squaredDistanceTransform(Int3 size, const std::vector<std::uint8_t>& feature,
                                             std::vector<std::int32_t>* nearest) {
    std::vector<double> grid(feature.size());
    std::vector<std::int32_t> from;
    if (nearest) from.assign(feature.size(), -1);
    for (std::size_t i = 0; i < feature.size(); ++i) {
        grid[i] = feature[i] ? 0.0 : kEdtInfinity;
        if (nearest && feature[i]) from[i] = static_cast<std::int32_t>(i);
    }
    for (int axis = 0; axis < 3; ++axis) transformAxis(grid, from, size, axis);
    if (nearest) *nearest = std::move(from);
    return grid;
}

DistanceField DistanceField::build(const VoxelWorld& world) {
    DistanceField field;
    field.size_ = world.size();
    const std::size_t cells =
        static_cast<std::size_t>(field.size_.x) * field.size_.y * field.size_.z;
    field.values_.assign(cells, kCap);
    field.features_.assign(cells, gpu::shared::kSdfNoFeature);
    const Int3 s = field.size_;
    field.compute(world, {-1, -1, -1}, {s.x + 1, s.y + 1, s.z + 1}, {0, 0, 0}, s);
    return field;
}

void DistanceField::update(const VoxelWorld& world, Int3 min, Int3 maxExclusive) {
    // Cells whose clamped value can change lie within r of the edit (r >= kCap + 1/2), and their
    // nearest features within r of them.
    const int r = static_cast<int>(std::ceil(kCap)) + 1;
    Int3 inLo, inHi, outLo, outHi;
    for (int a = 0; a < 3; ++a) {
        if (min[a] >= maxExclusive[a]) return;
        outLo[a] = std::clamp(min[a] - r, 0, size_[a]);
        outHi[a] = std::clamp(maxExclusive[a] + r, 0, size_[a]);
        inLo[a] = std::clamp(min[a] - 2 * r, -1, size_[a] + 1);
        inHi[a] = std::clamp(maxExclusive[a] + 2 * r, -1, size_[a] + 1);
        if (outLo[a] >= outHi[a]) return;
    }
    compute(world, inLo, inHi, outLo, outHi);
}

void DistanceField::compute(const VoxelWorld& world, Int3 inLo, Int3 inHi, Int3 outLo, Int3 outHi) {
    const Int3 box{inHi.x - inLo.x, inHi.y - inLo.y, inHi.z - inLo.z};
    const std::size_t count = static_cast<std::size_t>(box.x) * box.y * box.z;
    std::vector<std::uint8_t> solid(count), empty(count);
    parallelForRange(box.z, 1, [&](int begin, int end) {
        for (int z = begin; z < end; ++z) {
            for (int y = 0; y < box.y; ++y) {
                for (int x = 0; x < box.x; ++x) {
                    const std::size_t i = (static_cast<std::size_t>(z) * box.y + y) * box.x + x;
                    const bool s = world.solid(x + inLo.x, y + inLo.y, z + inLo.z);
                    solid[i] = s;
                    empty[i] = !s;
                }
            }
        }
    });
    std::vector<std::int32_t> nearSolid, nearEmpty;
    const std::vector<double> toSolid = squaredDistanceTransform(box, solid, &nearSolid);
    const std::vector<double> toEmpty = squaredDistanceTransform(box, empty, &nearEmpty);
    parallelForRange(outHi.z - outLo.z, 1, [&](int begin, int end) {
        for (int z = outLo.z + begin; z < outLo.z + end; ++z) {
            for (int y = outLo.y; y < outHi.y; ++y) {
                for (int x = outLo.x; x < outHi.x; ++x) {
                    const std::size_t i =
                        (static_cast<std::size_t>(z - inLo.z) * box.y + (y - inLo.y)) * box.x +
                        (x - inLo.x);
                    const double s =
                        solid[i] ? -(std::sqrt(toEmpty[i]) - 0.5) : std::sqrt(toSolid[i]) - 0.5;
                    values_[index(x, y, z)] =
                        static_cast<float>(std::clamp(s, double(-kCap), double(kCap)));
                    const std::int32_t f = solid[i] ? nearEmpty[i] : nearSolid[i];
                    std::uint32_t packed = gpu::shared::kSdfNoFeature;
                    // Only features that can matter under the cap: so a region update (which
                    // sees the voxels within 2 kCap + 2) names the same ones as a rebuild.
                    const double d2 = solid[i] ? toEmpty[i] : toSolid[i];
                    if (f >= 0 && d2 <= (kCap + 1.0) * (kCap + 1.0)) {
                        const int fx = f % box.x, fy = (f / box.x) % box.y,
                                  fz = f / (box.x * box.y);
                        packed = gpu::shared::packSdfFeature(
                            gpu::shared::ivec3(fx + inLo.x - x, fy + inLo.y - y, fz + inLo.z - z));
                    }
                    features_[index(x, y, z)] = packed;
                }
            }
        }
    });
}

float DistanceField::cell(int x, int y, int z) const {
    x = std::clamp(x, 0, size_.x - 1);
    y = std::clamp(y, 0, size_.y - 1);
    z = std::clamp(z, 0, size_.z - 1);
    return values_[index(x, y, z)];
}

double DistanceField::conservative(Vec3d p) const {
    const int cx = std::clamp(static_cast<int>(std::floor(p.x)), 0, size_.x - 1);
    const int cy = std::clamp(static_cast<int>(std::floor(p.y)), 0, size_.y - 1);
    const int cz = std::clamp(static_cast<int>(std::floor(p.z)), 0, size_.z - 1);
    const double s = values_[index(cx, cy, cz)];
    if (s <= 0.0) return s;  // a solid cell
    const Vec3d c{cx + 0.5, cy + 0.5, cz + 0.5};
    return (s + 0.5) - length(p - c) - kHalfDiagonal;
}

double DistanceField::surfaceDistance(Vec3d p) const {
    namespace sh = gpu::shared;
    const double fx = p.x - 0.5, fy = p.y - 0.5, fz = p.z - 0.5;
    const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy)),
              z0 = static_cast<int>(std::floor(fz));
    const bool inside =
        cornerValue(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)),
                    static_cast<int>(std::floor(p.z))) <= 0.0f;
    const sh::vec3 pf(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
    double best = kCap;
    for (int k = 0; k < 8; ++k) {
        const sh::ivec3 c(x0 + (k & 1), y0 + ((k >> 1) & 1), z0 + (k >> 2));
        best = std::min(best,
                        double(sh::sdfCornerCandidate(pf, c, cornerValue(c.x, c.y, c.z),
                                                      cornerFeature(c.x, c.y, c.z), inside, kCap)));
    }
    return inside ? -best : best;
}

float DistanceField::cornerValue(int x, int y, int z) const {
    if (x < 0 || y < 0 || z < 0 || x >= size_.x || y >= size_.y || z >= size_.z) return kCap;
    return values_[index(x, y, z)];
}

std::uint32_t DistanceField::cornerFeature(int x, int y, int z) const {
    if (x < 0 || y < 0 || z < 0 || x >= size_.x || y >= size_.y || z >= size_.z) {
        return gpu::shared::kSdfNoFeature;
    }
    return features_[index(x, y, z)];
}

double DistanceField::estimate(Vec3d p) const {
    const double fx = p.x - 0.5, fy = p.y - 0.5, fz = p.z - 0.5;
    const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy)),
              z0 = static_cast<int>(std::floor(fz));
    const double tx = fx - x0, ty = fy - y0, tz = fz - z0;
    double r = 0;
    for (int k = 0; k < 8; ++k) {
        const int dx = k & 1, dy = (k >> 1) & 1, dz = k >> 2;
        const double w = (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty) * (dz ? tz : 1 - tz);
        r += w * cell(x0 + dx, y0 + dy, z0 + dz);
    }
    return r;
}

}  // namespace luxel::voxel
