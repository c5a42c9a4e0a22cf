#include "gi2d/hrc/level_by_level.h"

#include <algorithm>
#include <bit>

#include "gi2d/hrc/cone_merge.h"
#include "gi2d/hrc/frustum_frame.h"
#include "gi2d/hrc/hrc_geometry.h"
#include "gi2d/hrc/near_lights.h"
#include "gi2d/hrc/ray_tables.h"
#include "gi2d/hrc/readout.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d::hrc {

std::uint64_t levelByLevelBytes(int width, int height) {
    std::uint64_t tables = 0, cones = 0;
    for (int r = 0; r < 2; ++r) {
        const FrustumFrame f = makeFrame(static_cast<Frustum>(r), width, height);
        const int levels = cascadeCount(f.length);
        tables = std::max(tables, RayTables::bytesFor(f.length, f.rows, levels));
        std::uint64_t most = 0;
        for (int n = 0; n < levels; ++n) {
            most = std::max(most, ConeBuffer::bytesFor(planeCount(f.length, n), pow2(n), f.rows));
        }
        cones = std::max(cones, 2 * most);
    }
    // The rotated medium lives while its marcher is built; the marcher lives for the frustum.
    const std::uint64_t frame = mediumBytes(width, height) + RayMarcher::bytesFor(width, height);
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;
    return tables + cones + frame + pixels * 3 * sizeof(float) +
           NearLightMask::hostBytesFor(width, height);
}

Image levelByLevelBeyond(const Medium2D& medium, const HrcOptions& options) {
    return levelByLevelBeyond(medium, options, NearLightMask::fromMedium(medium));
}

Image levelByLevelBeyond(const Medium2D& medium, const HrcOptions& options,
                         const NearLightMask& nearLights) {
    const int w = medium.width(), h = medium.height();
    Image beyond(w, h, 3);
    RayTables tables;
    ConeBuffer buffers[2];
    const int frustums = std::popcount(options.frustumMask & 0xFu);
    int done = 0;
    for (int r = 0; r < 4; ++r) {
        if (!(options.frustumMask & (1u << r))) continue;
        const FrustumFrame frame = makeFrame(static_cast<Frustum>(r), w, h);
        const int levels = cascadeCount(frame.length);
        {
            const RayMarcher marcher(frameMedium(medium, frame));
            tables.reset(frame.length, frame.rows, levels);
            traceBaseLevels(tables, marcher, options.tracedLevels);
        }
        extendLevels(tables, options.tracedLevels);

        const int lowest = std::max(options.debugCascade, 0);
        const ConeBuffer* upper = nullptr;
        int current = 0;
        for (int n = levels - 1; n >= lowest; --n) {
            mergeCascade(tables, n, upper, medium.boundaryRadiance, buffers[current],
                         {&nearLights, frame});
            upper = &buffers[current];
            current ^= 1;
        }
        readOut(frame, *upper, lowest, medium.boundaryRadiance, beyond);
        if (options.onProgress) options.onProgress(++done, frustums);
    }
    return beyond;
}

}  // namespace luxel::gi2d::hrc
