#include "luxel/octree/volume_generators.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "luxel/core/parallel.h"

namespace luxel::octree {
namespace {

// A value in [0, 1) from a hash of integers (deterministic, thread-independent).
double hashUnit(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    std::uint64_t h = a * 0x9e3779b97f4a7c15ull ^
                      (b + 0x632be59bd9b4e019ull) * 0xbf58476d1ce4e5b9ull ^
                      (c + 0x85ebca6b) * 0x94d049bb133111ebull;
    h ^= h >> 31;
    h *= 0xd6e8feb86659fd93ull;
    h ^= h >> 32;
    return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

Colour ramp(std::uint8_t opacity) {
    // Tissue (reddish) to bone (ivory).
    const double t = opacity / 255.0;
    return Colour{static_cast<std::uint8_t>(200 + 50 * t), static_cast<std::uint8_t>(90 + 150 * t),
                  static_cast<std::uint8_t>(80 + 140 * t), 1};
}

}  // namespace

Result<Volume> makePhantom(int side, std::uint64_t seed) {
    if (side < 8 || side > kMaxVolumeSide) {
        return Error("phantom side " + std::to_string(side) + " is outside 8.." +
                     std::to_string(kMaxVolumeSide));
    }
    auto created = Volume::create({side, side, side}, true);
    if (!created) return created.error();
    Volume& v = *created;
    const double s = side;
    const double shell = std::max(1.0, s / 170.0);
    struct Ball {
        double x, y, z, r;
    };
    std::vector<Ball> calcifications;
    for (int i = 0; i < 12; ++i) {
        calcifications.push_back({s * (0.35 + 0.3 * hashUnit(seed, i, 1)),
                                  s * (0.35 + 0.3 * hashUnit(seed, i, 2)),
                                  s * (0.35 + 0.3 * hashUnit(seed, i, 3)),
                                  std::max(1.0, s * 0.006 * (1 + hashUnit(seed, i, 4)))});
    }
    parallelForRange(side, 1, [&](int z0, int z1) {
        for (int z = z0; z < z1; ++z) {
            for (int y = 0; y < side; ++y) {
                for (int x = 0; x < side; ++x) {
                    // Head ellipsoid, normalised coordinates.
                    const double px = (x + 0.5) / s - 0.5, py = (y + 0.5) / s - 0.5,
                                 pz = (z + 0.5) / s - 0.5;
                    const double e =
                        std::sqrt((px / 0.36) * (px / 0.36) + (py / 0.44) * (py / 0.44) +
                                  (pz / 0.40) * (pz / 0.40));
                    if (e > 1.0) continue;
                    const double depthIn = (1.0 - e) * 0.4 * s;  // approximate voxels from the rim
                    std::uint8_t o;
                    if (depthIn < shell) {
                        o = 230;  // skull
                    } else {
                        const double ventricle =
                            std::hypot((px - 0.07) / 0.05, py / 0.12, pz / 0.08) < 1.0 ||
                            std::hypot((px + 0.07) / 0.05, py / 0.12, pz / 0.08) < 1.0;
                        o = ventricle ? 6
                                      : static_cast<std::uint8_t>(
                                            28 + 8 * hashUnit(seed, x / 4, y / 4 * 7919 + z / 4));
                        // One-voxel-thin shells at fixed radii: features a coarse step misses.
                        const double r = std::sqrt(px * px + py * py + pz * pz) * s;
                        for (double k : {0.12, 0.2, 0.28}) {
                            if (std::fabs(r - k * s) < 0.5) o = 150;
                        }
                        for (const Ball& b : calcifications) {
                            const double dx = x + 0.5 - b.x, dy = y + 0.5 - b.y, dz = z + 0.5 - b.z;
                            if (dx * dx + dy * dy + dz * dz < b.r * b.r) o = 255;
                        }
                    }
                    v.set(x, y, z, o, ramp(o));
                }
            }
        }
    });
    return created;
}

namespace {

class SparseTerrain final : public OctreeSource {
  public:
    SparseTerrain(int side, std::uint64_t seed) : side_(side) {
        for (int i = 0; i < 6; ++i) {
            const double f = (1 << i) * 2.0 * 3.14159265358979 / side;
            waves_.push_back({f * (0.6 + 0.8 * hashUnit(seed, i, 1)),
                              f * (0.6 + 0.8 * hashUnit(seed, i, 2)),
                              6.2831853 * hashUnit(seed, i, 3), side * 0.09 / (1 << i)});
        }
        amplitude_ = 0;
        for (const Wave& w : waves_) amplitude_ += w.amplitude;
    }
    Int3 size() const override { return {side_, side_, side_}; }
    bool hasColours() const override { return true; }

    void voxel(Int3 c, std::uint8_t& opacity, Colour& colour) const override {
        const int h = height(c.x, c.z);
        opacity = c.y < h ? 255 : 0;
        colour = materialAt(h - 1 - c.y);
    }

    std::optional<Uniform> uniformBlock(Int3 origin, int level) const override {
        if (level < 2) return std::nullopt;
        const int n = 1 << level;
        // Height bounds of the block's columns from the wave amplitudes and slopes: a cheap,
        // conservative range over the block's footprint.
        const double cx = origin.x + n * 0.5, cz = origin.z + n * 0.5;
        const double centre = heightAt(cx, cz);
        double slope = 0;
        for (const Wave& w : waves_) slope += w.amplitude * (w.fx + w.fz);
        const double reach = slope * n * 0.5 + 1.0;
        const double lo = centre - reach, hi = centre + reach;
        if (origin.y >= hi) return Uniform{};                                  // all air
        if (origin.y + n <= lo - kDirtDepth - 1) return Uniform{255, kStone};  // all stone
        return std::nullopt;
    }

  private:
    struct Wave {
        double fx, fz, phase, amplitude;
    };
    static constexpr int kDirtDepth = 4;
    static constexpr Colour kGrass{86, 150, 60, 1}, kDirt{120, 85, 55, 1}, kStone{125, 125, 130, 1};

    double heightAt(double x, double z) const {
        double h = side_ * 0.4;
        for (const Wave& w : waves_)
            h += w.amplitude * std::sin(w.fx * x + w.phase) * std::cos(w.fz * z);
        return h;
    }
    int height(int x, int z) const {
        return static_cast<int>(std::floor(heightAt(x + 0.5, z + 0.5)));
    }
    static Colour materialAt(int below) {
        return below <= 0 ? kGrass : (below <= kDirtDepth ? kDirt : kStone);
    }

    int side_;
    std::vector<Wave> waves_;
    double amplitude_ = 0;
};

}  // namespace

std::unique_ptr<OctreeSource> makeSparseTerrain(int side, std::uint64_t seed) {
    return std::make_unique<SparseTerrain>(side, seed);
}

}  // namespace luxel::octree
