// Procedural voxel worlds: fBm terrain, random fill, spheres and boxes.
#include "luxel/voxel/generators.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "luxel/core/parallel.h"
#include "luxel/core/rng.h"
#include "noise.h"

namespace luxel::voxel {
namespace {

// Calls body(x0, x1, z0, z1) in parallel on the world's chunk columns. A task owns every chunk of
// its column, so VoxelWorld::set (which updates per-chunk solid counts) never races.
template <typename Body>
void forEachChunkColumn(const VoxelWorld& world, Body&& body) {
    const Int3 size = world.size(), chunks = world.chunkCount();
    const int cs = world.chunkSize();
    parallelForRange(chunks.x * chunks.z, 1, [&](int begin, int end) {
        for (int c = begin; c < end; ++c) {
            const int cx = c % chunks.x, cz = c / chunks.x;
            body(cx * cs, std::min(size.x, (cx + 1) * cs), cz * cs,
                 std::min(size.z, (cz + 1) * cs));
        }
    });
}

std::string formatDouble(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

Status checkRange(const char* name, double v, double lo, double hi, bool openLo = false) {
    const bool ok = std::isfinite(v) && (openLo ? v > lo : v >= lo) && v <= hi;
    if (ok) return Ok{};
    return Error(std::string("terrain option ") + name + " must be in " + (openLo ? "(" : "[") +
                 formatDouble(lo) + ", " + formatDouble(hi) + "], got " + formatDouble(v));
}

constexpr Voxel kWater{40, 90, 200, 255};
constexpr Voxel kSand{218, 200, 140, 255};
constexpr Voxel kGrass{80, 150, 60, 255};
constexpr Voxel kRock{120, 115, 110, 255};
constexpr Voxel kSnow{240, 244, 250, 255};
constexpr Voxel kDirt{110, 85, 60, 255};

// A small deterministic brightness jitter so flat areas are not one flat colour.
Voxel jitter(Voxel v, std::uint64_t h) {
    const int d = static_cast<int>(h & 15) - 8;
    auto channel = [d](std::uint8_t c) {
        return static_cast<std::uint8_t>(std::clamp(static_cast<int>(c) + d, 0, 255));
    };
    return {channel(v.r), channel(v.g), channel(v.b), v.a};
}

std::uint64_t voxelHash(std::uint64_t seed, int x, int y, int z) {
    return hashSeed(seed,
                    (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) |
                        static_cast<std::uint32_t>(y),
                    static_cast<std::uint64_t>(static_cast<std::uint32_t>(z)));
}

}  // namespace

Status validateTerrainOptions(const TerrainOptions& o) {
    const Status checks[] = {
        checkRange("baseHeight", o.baseHeight, 0, 1),
        checkRange("amplitude", o.amplitude, 0, 1),
        checkRange("frequency", o.frequency, 0, 1, true),
        checkRange("octaves", o.octaves, 1, 16),
        checkRange("lacunarity", o.lacunarity, 1, 4),
        checkRange("gain", o.gain, 0, 1, true),
        checkRange("waterLevel", o.waterLevel, 0, 1),
        checkRange("rockLine", o.rockLine, 0, 1),
        checkRange("snowLine", o.snowLine, 0, 1),
        checkRange("steepSlope", o.steepSlope, 1, kMaxWorldSide),
        checkRange("caveFrequency", o.caveFrequency, 0, 1, true),
        checkRange("caveThreshold", o.caveThreshold, -1, 1),
    };
    for (const Status& s : checks) {
        if (!s) return s;
    }
    return Ok{};
}

Status generateTerrain(VoxelWorld& world, const TerrainOptions& o) {
    if (Status s = validateTerrainOptions(o); !s) return s;
    const Int3 size = world.size();
    const int w = size.x, h = size.y, d = size.z;
    const GradientNoise heightNoise(hashSeed(o.seed, 1)), caveNoise(hashSeed(o.seed, 2));
    const auto freq = static_cast<float>(o.frequency), lac = static_cast<float>(o.lacunarity),
               gain = static_cast<float>(o.gain), caveFreq = static_cast<float>(o.caveFrequency),
               caveThreshold = static_cast<float>(o.caveThreshold);

    // Pass 1: ground height per column (number of solid voxels, at least 1 so there is a floor).
    std::vector<int> ground(static_cast<std::size_t>(w) * d);
    parallelForRange(d, 1, [&](int z0, int z1) {
        for (int z = z0; z < z1; ++z) {
            for (int x = 0; x < w; ++x) {
                const float n = heightNoise.fbm2(x * freq, z * freq, o.octaves, lac, gain);
                const double top = (o.baseHeight + o.amplitude * n) * h;
                ground[static_cast<std::size_t>(z) * w + x] =
                    std::clamp(static_cast<int>(std::lround(top)), 1, h);
            }
        }
    });
    auto groundAt = [&](int x, int z) {
        x = std::clamp(x, 0, w - 1);
        z = std::clamp(z, 0, d - 1);
        return ground[static_cast<std::size_t>(z) * w + x];
    };

    // Pass 2: fill columns. Everything written depends only on (x, y, z) and the heights.
    const int water = static_cast<int>(o.waterLevel * h);
    const int rockY = static_cast<int>(o.rockLine * h), snowY = static_cast<int>(o.snowLine * h);
    forEachChunkColumn(world, [&](int x0, int x1, int z0, int z1) {
        for (int z = z0; z < z1; ++z) {
            for (int x = x0; x < x1; ++x) {
                const int g = groundAt(x, z);
                const int slope =
                    std::max({std::abs(g - groundAt(x - 1, z)), std::abs(g - groundAt(x + 1, z)),
                              std::abs(g - groundAt(x, z - 1)), std::abs(g - groundAt(x, z + 1))});
                const int surfaceY = g - 1;
                Voxel surface = kGrass;
                if (slope >= o.steepSlope) {
                    surface = kRock;
                } else if (surfaceY < water + 2) {
                    surface = kSand;
                } else if (surfaceY >= snowY) {
                    surface = kSnow;
                } else if (surfaceY >= rockY) {
                    surface = kRock;
                }
                for (int y = 0; y < h; ++y) {
                    Voxel v{};
                    if (y < g) {
                        const bool carved = o.caves && y >= 1 && y < g - 3 &&
                                            caveNoise.fbm3(x * caveFreq, y * caveFreq, z * caveFreq,
                                                           3, 2.0f, 0.5f) > caveThreshold;
                        if (!carved) {
                            const Voxel base = y >= g - 3 ? surface : (y >= g - 6 ? kDirt : kRock);
                            v = jitter(base, voxelHash(o.seed, x, y, z));
                        }
                    } else if (y < water) {
                        v = kWater;
                    }
                    world.set(x, y, z, v);
                }
            }
        }
    });
    world.refreshEmptySpace();
    return Ok{};
}

Status fillRandom(VoxelWorld& world, double density, std::uint64_t seed,
                  std::optional<Voxel> colour) {
    if (!(density >= 0.0 && density <= 1.0)) {
        return Error("random fill density must be in [0, 1], got " + formatDouble(density));
    }
    if (colour && colour->a == 0) colour->a = 1;
    const int h = world.size().y;
    forEachChunkColumn(world, [&](int x0, int x1, int z0, int z1) {
        for (int z = z0; z < z1; ++z) {
            for (int y = 0; y < h; ++y) {
                for (int x = x0; x < x1; ++x) {
                    const std::uint64_t r = voxelHash(seed, x, y, z);
                    // 53 bits -> [0, 1): u < 1 always, so density 1 fills everything.
                    const double u = static_cast<double>(r >> 11) * 0x1p-53;
                    Voxel v{};
                    if (u < density) {
                        if (colour) {
                            v = *colour;
                        } else {
                            const std::uint64_t c = mix64(r);
                            v = {static_cast<std::uint8_t>(c), static_cast<std::uint8_t>(c >> 8),
                                 static_cast<std::uint8_t>(c >> 16), 255};
                        }
                    }
                    world.set(x, y, z, v);
                }
            }
        }
    });
    world.refreshEmptySpace();
    return Ok{};
}

void addSphere(VoxelWorld& world, Vec3 centre, float radius, Voxel v) {
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(centre.z) ||
        !(radius >= 0.0f)) {
        return;
    }
    const Int3 size = world.size();
    const double r = radius, r2 = r * r;
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        // Centres i + 0.5 within [c - r, c + r]; clamped in double before converting to int.
        const double c = centre[a];
        lo[a] = static_cast<int>(std::clamp(std::floor(c - r - 0.5), 0.0, double(size[a])));
        hi[a] = static_cast<int>(std::clamp(std::ceil(c + r - 0.5), -1.0, double(size[a] - 1)));
    }
    for (int z = lo[2]; z <= hi[2]; ++z) {
        for (int y = lo[1]; y <= hi[1]; ++y) {
            for (int x = lo[0]; x <= hi[0]; ++x) {
                const double dx = x + 0.5 - centre.x, dy = y + 0.5 - centre.y,
                             dz = z + 0.5 - centre.z;
                if (dx * dx + dy * dy + dz * dz <= r2) world.set(x, y, z, v);
            }
        }
    }
    world.refreshEmptySpace();
}

void addBox(VoxelWorld& world, Int3 min, Int3 maxExclusive, Voxel v) {
    const Int3 size = world.size();
    Int3 lo, hi;
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::max(min[a], 0);
        hi[a] = std::min(maxExclusive[a], size[a]);
    }
    for (int z = lo.z; z < hi.z; ++z) {
        for (int y = lo.y; y < hi.y; ++y) {
            for (int x = lo.x; x < hi.x; ++x) world.set(x, y, z, v);
        }
    }
    world.refreshEmptySpace();
}

}  // namespace luxel::voxel
