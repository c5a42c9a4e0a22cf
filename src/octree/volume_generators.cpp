#include "luxel/octree/volume_generators.h"

#include <algorithm>
#include <atomic>
#include <climits>
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

constexpr double kPi = 3.14159265358979323846;

// The range of sin over [a, b]: the endpoints, or +-1 where a peak lies inside.
void sinRange(double a, double b, double& lo, double& hi) {
    if (b - a >= 2 * kPi) {
        lo = -1;
        hi = 1;
        return;
    }
    lo = std::min(std::sin(a), std::sin(b));
    hi = std::max(std::sin(a), std::sin(b));
    // The first peak (pi/2 + 2k pi) and trough (-pi/2 + 2k pi) at or after a.
    const double peak = kPi / 2 + 2 * kPi * std::ceil((a - kPi / 2) / (2 * kPi));
    const double trough = -kPi / 2 + 2 * kPi * std::ceil((a + kPi / 2) / (2 * kPi));
    if (peak <= b) hi = 1;
    if (trough <= b) lo = -1;
}

// Column heights of the terrain over square tiles, computed together and cached per thread:
// each wave is a product of a function of x and one of z, so a tile of n x n columns costs 2n
// sines and cosines per wave instead of 2n^2, with the same arithmetic (and so the same heights)
// as evaluating every column alone. Per tile, min and max heights over every aligned sub-square
// (a mip pyramid) answer uniformBlock exactly for blocks up to the tile's width.
class SparseTerrain final : public OctreeSource {
  public:
    SparseTerrain(int side, std::uint64_t seed) : side_(side), id_(nextId()) {
        for (int i = 0; i < 6; ++i) {
            const double f = (1 << i) * 2.0 * 3.14159265358979 / side;
            waves_.push_back({f * (0.6 + 0.8 * hashUnit(seed, i, 1)),
                              f * (0.6 + 0.8 * hashUnit(seed, i, 2)),
                              6.2831853 * hashUnit(seed, i, 3), side * 0.09 / (1 << i)});
        }
    }
    Int3 size() const override { return {side_, side_, side_}; }
    bool hasColours() const override { return true; }

    void voxel(Int3 c, std::uint8_t& opacity, Colour& colour) const override {
        const int h = tileOf(c.x, c.z).height(c.x & kTileMask, c.z & kTileMask);
        opacity = c.y < h ? 255 : 0;
        colour = materialAt(h - 1 - c.y);
    }

    std::optional<Uniform> uniformBlock(Int3 origin, int level) const override {
        const int n = 1 << level;
        // A column of height h is solid below h; its top voxel is grass, the next kDirtDepth dirt.
        auto answer = [&](int lo, int hi) -> std::optional<Uniform> {
            if (origin.y >= hi) return Uniform{};                                  // all air
            if (origin.y + n <= lo - kDirtDepth - 1) return Uniform{255, kStone};  // all stone
            return std::nullopt;
        };
        int lo, hi;  // least and greatest column height over the block's footprint
        if (level <= kTileShift) {
            tileOf(origin.x, origin.z)
                .range(origin.x & kTileMask, origin.z & kTileMask, level, lo, hi);
            return answer(lo, hi);
        }
        boundHeights(origin.x, origin.z, n, lo, hi);
        auto bounded = answer(lo, hi);
        if (bounded || level > kExactShift) return bounded;
        // The bounds are loose on steep ground: a few tiles give the exact range.
        lo = INT_MAX;
        hi = INT_MIN;
        for (int z = origin.z; z < origin.z + n; z += kTile) {
            for (int x = origin.x; x < origin.x + n; x += kTile) {
                int l, u;
                tileOf(x, z).range(0, 0, kTileShift, l, u);
                lo = std::min(lo, l);
                hi = std::max(hi, u);
            }
        }
        return answer(lo, hi);
    }

  private:
    struct Wave {
        double fx, fz, phase, amplitude;
    };
    static constexpr int kDirtDepth = 4;
    static constexpr Colour kGrass{86, 150, 60, 1}, kDirt{120, 85, 55, 1}, kStone{125, 125, 130, 1};
    static constexpr int kTileShift = 5, kTile = 1 << kTileShift, kTileMask = kTile - 1;
    // Blocks up to this level (at most 16 tiles) get exact answers; wider ones only the bounds.
    static constexpr int kExactShift = kTileShift + 2;

    struct Tile {
        std::uint64_t owner = 0;  // the terrain's id; 0 = empty
        int x0 = 0, z0 = 0;
        int heights[kTile * kTile];
        // Level l (1..kTileShift) holds (kTile >> l)^2 pairs of min and max from offset[l].
        int mips[2 * (kTile * kTile / 3 + 1)];

        int height(int x, int z) const { return heights[z * kTile + x]; }
        void range(int x, int z, int level, int& lo, int& hi) const {
            if (level == 0) {
                lo = hi = height(x, z);
                return;
            }
            const int w = kTile >> level;
            const int* m = &mips[2 * (offset(level) + (z >> level) * w + (x >> level))];
            lo = m[0];
            hi = m[1];
        }
        static int offset(int level) {
            int o = 0;
            for (int l = 1; l < level; ++l) o += (kTile >> l) * (kTile >> l);
            return o;
        }
    };
    static constexpr int kCachedTiles = 64;
    struct Cache {
        Tile tiles[kCachedTiles];
    };

    static std::uint64_t nextId() {
        static std::atomic<std::uint64_t> counter{0};
        return ++counter;
    }

    const Tile& tileOf(int x, int z) const {
        // Per thread: the builder reads from several threads, and a tile is used by the blocks
        // above and below it within a short span of the recursion.
        thread_local std::unique_ptr<Cache> cache;
        if (!cache) cache = std::make_unique<Cache>();
        const int x0 = x & ~kTileMask, z0 = z & ~kTileMask;
        Tile& tile =
            cache->tiles[((x0 >> kTileShift) * 7 + (z0 >> kTileShift) * 3) & (kCachedTiles - 1)];
        if (tile.owner != id_ || tile.x0 != x0 || tile.z0 != z0) fill(tile, x0, z0);
        return tile;
    }

    // A column's height is floor(side * 0.4 + sum of amplitude * sin(fx x + phase) * cos(fz z)) at
    // its centre, summed wave by wave in this order (so every tile gives the same heights).
    void fill(Tile& tile, int x0, int z0) const {
        tile.owner = id_;
        tile.x0 = x0;
        tile.z0 = z0;
        double h[kTile * kTile];
        std::fill(h, h + kTile * kTile, side_ * 0.4);
        for (const Wave& w : waves_) {
            double sx[kTile], cz[kTile];
            for (int i = 0; i < kTile; ++i) {
                sx[i] = w.amplitude * std::sin(w.fx * (x0 + i + 0.5) + w.phase);
                cz[i] = std::cos(w.fz * (z0 + i + 0.5));
            }
            for (int z = 0; z < kTile; ++z) {
                for (int x = 0; x < kTile; ++x) h[z * kTile + x] += sx[x] * cz[z];
            }
        }
        for (int i = 0; i < kTile * kTile; ++i)
            tile.heights[i] = static_cast<int>(std::floor(h[i]));
        for (int level = 1; level <= kTileShift; ++level) {
            const int w = kTile >> level;
            for (int z = 0; z < w; ++z) {
                for (int x = 0; x < w; ++x) {
                    int lo = INT_MAX, hi = INT_MIN;
                    for (int q = 0; q < 4; ++q) {
                        int l, u;
                        tile.range(((x << 1) | (q & 1)) << (level - 1),
                                   ((z << 1) | (q >> 1)) << (level - 1), level - 1, l, u);
                        lo = std::min(lo, l);
                        hi = std::max(hi, u);
                    }
                    int* m = &tile.mips[2 * (Tile::offset(level) + z * w + x)];
                    m[0] = lo;
                    m[1] = hi;
                }
            }
        }
    }

    // Conservative height bounds over the n x n columns from (x0, z0), wave by wave from the
    // exact ranges of its sine and cosine factors over the footprint (interval arithmetic): far
    // tighter than a global slope bound where the ground is flat.
    void boundHeights(int x0, int z0, int n, int& lo, int& hi) const {
        double sumLo = side_ * 0.4, sumHi = side_ * 0.4;
        for (const Wave& w : waves_) {
            double sLo, sHi, cLo, cHi;
            sinRange(w.fx * (x0 + 0.5) + w.phase, w.fx * (x0 + n - 0.5) + w.phase, sLo, sHi);
            sinRange(w.fz * (z0 + 0.5) + kPi / 2, w.fz * (z0 + n - 0.5) + kPi / 2, cLo, cHi);
            const double p[4] = {sLo * cLo, sLo * cHi, sHi * cLo, sHi * cHi};
            sumLo += w.amplitude * *std::min_element(p, p + 4);
            sumHi += w.amplitude * *std::max_element(p, p + 4);
        }
        // Rounding of the sums and of sin and cos is far below this margin.
        lo = static_cast<int>(std::floor(sumLo - 1e-6));
        hi = static_cast<int>(std::floor(sumHi + 1e-6));
    }

    static Colour materialAt(int below) {
        return below <= 0 ? kGrass : (below <= kDirtDepth ? kDirt : kStone);
    }

    int side_;
    std::uint64_t id_;  // tags this terrain's tiles in the per-thread caches
    std::vector<Wave> waves_;
};

}  // namespace

std::unique_ptr<OctreeSource> makeSparseTerrain(int side, std::uint64_t seed) {
    return std::make_unique<SparseTerrain>(side, seed);
}

}  // namespace luxel::octree
