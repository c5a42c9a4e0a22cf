// A pixel's tile state (shared/octree_tiles_layout.h) as the public TilePixel, for the CPU twin
// and the GPU pass alike.
#pragma once

#include "gpu/shaders/shared/octree_tiles_layout.h"
#include "luxel/octree/octree_tiles.h"

namespace luxel::octree {

inline TilePixel tilePixelOf(const gpu::shared::OctreeTileState& s) {
    TilePixel p;
    p.hit = s.status == LUXEL_OCTREE_TILE_FOUND;
    p.deadEnd = s.status == LUXEL_OCTREE_TILE_DEAD_END;
    if (p.hit) {
        p.cell = {s.cellX, s.cellY, s.cellZ};
        p.level = static_cast<int>(s.level);
        p.entry = s.entry;
    }
    p.samples = static_cast<int>(s.samples);
    return p;
}

}  // namespace luxel::octree
