// Probe grids of the voxel radiance cascades (cascade_layout.h).
#include "cascade_layout.h"

#include <algorithm>
#include <cmath>

namespace luxel::voxel::cascades {

Int3 Level::probeCell(std::int64_t probe) const {
    const int x = int(probe % probes.x);
    const int y = int((probe / probes.x) % probes.y);
    const int z = int(probe / (std::int64_t(probes.x) * probes.y));
    return {x, y, z};
}

double Level::offset() const {
    return spacing / 2 + 0.5;
}

Vec3d Level::position(std::int64_t probe) const {
    const Int3 c = probeCell(probe);
    return Vec3d{double(c.x), double(c.y), double(c.z)} * double(spacing) +
           Vec3d{offset(), offset(), offset()};
}

Corners cornersAround(const Level& level, Vec3d point) {
    Corners out;
    int base[3];
    float frac[3];
    for (int a = 0; a < 3; ++a) {
        const double u =
            std::clamp(point[a] / level.spacing - 0.5, 0.0, double(level.probes[a] - 1));
        base[a] = std::min(int(std::floor(u)), std::max(0, level.probes[a] - 2));
        frac[a] = float(u - base[a]);
    }
    for (int i = 0; i < 8; ++i) {
        int cell[3];
        float w = 1.0f;
        for (int a = 0; a < 3; ++a) {
            const int bit = (i >> a) & 1;
            cell[a] = std::min(base[a] + bit, level.probes[a] - 1);
            w *= bit ? frac[a] : 1.0f - frac[a];
        }
        out.probe[i] = std::int32_t(
            (std::int64_t(cell[2]) * level.probes.y + cell[1]) * level.probes.x + cell[0]);
        out.weight[i] = w;
    }
    return out;
}

std::vector<Level> planLevels(Int3 worldSize, int spacing) {
    const int longest = std::max({worldSize.x, worldSize.y, worldSize.z});
    std::vector<Level> levels;
    for (int k = 0;; ++k) {
        Level level;
        level.spacing = spacing << k;
        for (int a = 0; a < 3; ++a) {
            level.probes[a] = std::max(1, (worldSize[a] + level.spacing - 1) / level.spacing);
        }
        level.binSide = kFaceBinSide << k;
        level.tStart = kStartPerSpacing * level.spacing;
        levels.push_back(level);
        if (2 * level.spacing >= longest || k >= 12) break;
    }
    levels.back().top = true;
    return levels;
}

std::uint64_t cascadeBytes(const std::vector<Level>& levels, std::int64_t faces, int binsPerFace) {
    std::uint64_t bytes = 0;
    for (std::size_t k = 0; k < levels.size(); ++k) {
        const std::uint64_t entries =
            std::uint64_t(levels[k].probeCount()) * levels[k].binSide * levels[k].binSide;
        bytes += entries * (levels[k].top ? 4 : 4 * 8) + entries * 12;  // codes, radiance
        bytes += entries / 4 * 12;                                      // child means
        bytes += std::uint64_t(levels[k].probeCount()) * sizeof(Corners);
    }
    // Its bins x 8 codes, plus its colours, corners, radiance cache and neighbours' ids.
    bytes += std::uint64_t(faces) *
             (std::uint64_t(binsPerFace) * 8 * 4 + sizeof(Corners) + 6 * 12 + 4 + 4 + 24 + 32);
    return bytes;
}

}  // namespace luxel::voxel::cascades
