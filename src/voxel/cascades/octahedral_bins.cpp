// Octahedral direction bins (octahedral_bins.h; docs/algorithms/voxel-radiance-cascades.md §2).
#include "octahedral_bins.h"

#include "luxel/core/parallel.h"

#include <cmath>

namespace luxel::voxel::cascades {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The octahedron point (|x| + |y| + |z| = 1) at (u, v): a = 2u - 1, b = 2v - 1 lie in the upper
// hemisphere's diamond |a| + |b| <= 1 or in one of the four folded corners below.
Vec3d octahedronPoint(double u, double v) {
    double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
    const double y = 1.0 - std::abs(a) - std::abs(b);
    if (y < 0.0) {
        const double fa = (1.0 - std::abs(b)) * (a < 0.0 ? -1.0 : 1.0);
        const double fb = (1.0 - std::abs(a)) * (b < 0.0 ? -1.0 : 1.0);
        a = fa, b = fb;
    }
    return {a, y, b};
}

// Sub-samples per bin side for the numerical integrals: fine enough for 1e-4 relative accuracy
// on coarse maps, fewer on fine ones (where each bin is small).
int subSamples(int side) {
    return std::max(4, 64 / side);
}

// Calls f(direction, d omega) at each sub-sample of `bin`. The map's Jacobian: with p the
// octahedron point, d omega = |p . (dp/da x dp/db)| / |p|^3 da db = da db / |p|^3 (the triple
// product is 1 on every face), and da db = 4 du dv.
template <typename F>
void forEachSample(int side, int bin, F&& f) {
    const int bx = bin % side, by = bin / side, s = subSamples(side);
    const double cell = 1.0 / (double(side) * s);
    for (int j = 0; j < s; ++j) {
        for (int i = 0; i < s; ++i) {
            const double u = (bx * s + i + 0.5) * cell, v = (by * s + j + 0.5) * cell;
            const Vec3d p = octahedronPoint(u, v);
            const double len = length(p);
            f(p / len, 4.0 * cell * cell / (len * len * len));
        }
    }
}

}  // namespace

Vec3d octahedralDirection(double u, double v) {
    return normalize(octahedronPoint(u, v));
}

DirectionBins DirectionBins::build(int side) {
    DirectionBins bins;
    bins.side = side;
    const int count = side * side;
    bins.centre.resize(count);
    bins.solidAngle.assign(count, 0.0);
    std::array<std::vector<double>, 6> cosine;
    std::array<std::vector<Vec3d>, 6> mean;
    for (auto& c : cosine) c.assign(count, 0.0);
    for (auto& m : mean) m.assign(count, Vec3d{});
    double total = 0.0;
    for (int bin = 0; bin < count; ++bin) {
        bins.centre[bin] =
            octahedralDirection((bin % side + 0.5) / side, (bin / side + 0.5) / side);
        forEachSample(side, bin, [&](Vec3d w, double dw) {
            bins.solidAngle[bin] += dw;
            for (int n = 0; n < 6; ++n) {
                const Int3 a = normalFromIndex(n);
                const double c = a.x * w.x + a.y * w.y + a.z * w.z;
                if (c > 0.0) {
                    cosine[n][bin] += c * dw;
                    mean[n][bin] = mean[n][bin] + w * (c * dw);
                }
            }
        });
        total += bins.solidAngle[bin];
    }
    // Normalise away the last 1e-5 of integration error: a uniform radiance must give 4 pi and pi.
    for (double& a : bins.solidAngle) a *= 4.0 * kPi / total;
    for (int n = 0; n < 6; ++n) {
        double sum = 0.0;
        for (double c : cosine[n]) sum += c;
        for (int bin = 0; bin < count; ++bin) {
            if (cosine[n][bin] <= 0.0) continue;
            bins.cosine[n].bin.push_back(bin);
            bins.cosine[n].weight.push_back(float(cosine[n][bin] * kPi / sum));
            bins.cosine[n].direction.push_back(normalize(mean[n][bin]));
        }
    }
    return bins;
}

int DirectionBins::parent(int bin) const {
    const int half = side / 2;
    return (bin / side / 2) * half + (bin % side) / 2;
}

std::array<int, 4> DirectionBins::children(int bin) const {
    const int fine = side * 2, bx = 2 * (bin % side), by = 2 * (bin / side);
    return {by * fine + bx, by * fine + bx + 1, (by + 1) * fine + bx, (by + 1) * fine + bx + 1};
}

std::vector<Rgb> skyMeans(const DirectionBins& bins, const ShadeOptions& shading,
                          const std::vector<bool>* wanted) {
    std::vector<Rgb> means(bins.count());
    // Each bin on its own: the same means on any number of threads.
    parallelForRange(bins.count(), 16, [&](int begin, int end) {
        for (int bin = begin; bin < end; ++bin) {
            if (wanted && !(*wanted)[bin]) continue;
            double sum[3] = {0, 0, 0}, area = 0.0;
            forEachSample(bins.side, bin, [&](Vec3d w, double dw) {
                const Rgb sky = skyColor(w, shading);
                for (int c = 0; c < 3; ++c) sum[c] += sky[c] * dw;
                area += dw;
            });
            means[bin] = Rgb(float(sum[0] / area), float(sum[1] / area), float(sum[2] / area));
        }
    });
    return means;
}

}  // namespace luxel::voxel::cascades
