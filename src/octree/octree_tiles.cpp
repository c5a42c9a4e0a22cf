// renderOctreeTiles: the shared tile kernel (shared/octree_tiles.h) in double, pass after pass
// over the whole image, as the GPU runs one dispatch per pass; and the comparison with the
// exact traversal.
#include "luxel/octree/octree_tiles.h"

#include <algorithm>
#include <limits>
#include <string>

#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "octree/octree_access.h"
#include "octree/octree_render_params.h"
#include "octree/octree_tiles_state.h"
// After octree_access.h, which defines the accessors the kernel reads the tree through.
#include "gpu/shaders/shared/octree_tiles.h"

namespace luxel::octree {

namespace shared = gpu::shared;

Status validateTileOptions(const TileOptions& o) {
    if (o.tileBits < 1 || o.tileBits > kMaxDepth) {
        return Error("tile options: tile bits must be in 1.." + std::to_string(kMaxDepth));
    }
    if (o.passes < 0 || o.passes > kMaxDepth) {
        return Error("tile options: passes must be in 0.." + std::to_string(kMaxDepth));
    }
    return Ok{};
}

int tilePassCount(int depth, int tileBits) {
    return (depth + tileBits - 1) / tileBits;
}

int tilePassLevel(int depth, int tileBits, int pass) {
    return tileBits * (tilePassCount(depth, tileBits) - 1 - pass);
}

Result<TileRender> renderOctreeTiles(const Octree& tree, const voxel::Camera& camera,
                                     const OctreeRenderOptions& options, const TileOptions& tiles) {
    if (Status s = validateRenderOptions(options); !s) return s.error();
    if (Status s = validateTileOptions(tiles); !s) return s.error();
    const std::uint64_t pixels = static_cast<std::uint64_t>(camera.width()) * camera.height();
    if (Status s = checkMemory(pixels * sizeof(shared::OctreeTileState), "tile states"); !s) {
        return s.error();
    }
    OctreeRenderOptions surface = options;
    surface.mode = OctreeMode::Surface;
    const shared::OctreeRenderParams p = renderParams(tree, camera, surface);
    const OctreeArrays arrays = arraysOf(tree);
    const int count = tilePassCount(tree.depth, tiles.tileBits);
    const int run = tiles.passes > 0 ? std::min(tiles.passes, count) : count;
    std::vector<shared::OctreeTileState> states(pixels);
    const int width = camera.width();
    // Pass by pass over the whole image, as the GPU dispatches them.
    for (int pass = 0; pass < run; ++pass) {
        const int level = tilePassLevel(tree.depth, tiles.tileBits, pass);
        const int parent =
            pass == 0 ? tree.depth : tilePassLevel(tree.depth, tiles.tileBits, pass - 1);
        parallelForRange(camera.height(), 1, [&](int begin, int end) {
            for (int y = begin; y < end; ++y) {
                for (int x = 0; x < width; ++x) {
                    shared::dvec3 o, d;
                    shared::octreePixelRay(p, x, y, o, d);
                    shared::OctreeTileState& s = states[static_cast<std::size_t>(y) * width + x];
                    s = shared::octreeTilesPass(arrays, p, o, d, s, shared::uint(pass), level,
                                                parent);
                }
            }
        });
    }
    TileRender out{Image(width, camera.height(), 3), std::vector<TilePixel>(pixels)};
    parallelForRange(camera.height(), 1, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < width; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * width + x;
                shared::dvec3 o, d;
                shared::octreePixelRay(p, x, y, o, d);
                const shared::vec3 c =
                    shared::octreeTilesShade(arrays, p, o, d, states[i], shared::uint(i));
                out.image.setRgb(x, y, Rgb(c.x, c.y, c.z));
                out.pixels[i] = tilePixelOf(states[i]);
            }
        }
    });
    return out;
}

std::vector<TilePixel> exactPixels(const Octree& tree, const voxel::Camera& camera,
                                   const OctreeRenderOptions& options) {
    const shared::OctreeRenderParams p = renderParams(tree, camera, options);
    const OctreeArrays arrays = arraysOf(tree);
    const int width = camera.width();
    std::vector<TilePixel> out(static_cast<std::size_t>(width) * camera.height());
    parallelForRange(camera.height(), 1, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < width; ++x) {
                shared::dvec3 o, d;
                shared::octreePixelRay(p, x, y, o, d);
                shared::uint entry = 0;
                const shared::VoxelTrace trace =
                    shared::octreeTraverse(arrays, tree.depth, shared::octreeParamsSize(p), o, d,
                                           std::numeric_limits<double>::infinity(),
                                           static_cast<int>(p.stepCap), p.threshold, entry);
                TilePixel& px = out[static_cast<std::size_t>(y) * width + x];
                px.hit = trace.hit;
                if (trace.hit) px.cell = {trace.cell.x, trace.cell.y, trace.cell.z};
                px.entry = entry;
                px.samples = trace.steps;
            }
        }
    });
    return out;
}

double TileComparison::differingPercent() const {
    return pixels > 0 ? 100.0 * static_cast<double>(differentVoxel + missedSurface + falseHit) /
                            static_cast<double>(pixels)
                      : 0.0;
}

double TileComparison::missedPercent() const {
    return pixels > 0 ? 100.0 * static_cast<double>(missedSurface) / static_cast<double>(pixels)
                      : 0.0;
}

Result<TileComparison> compareTiles(const std::vector<TilePixel>& tiles,
                                    const std::vector<TilePixel>& exact) {
    if (tiles.size() != exact.size()) {
        return Error("tile comparison: " + std::to_string(tiles.size()) + " tile pixels but " +
                     std::to_string(exact.size()) + " exact ones");
    }
    TileComparison c;
    c.pixels = static_cast<std::int64_t>(tiles.size());
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        const TilePixel& t = tiles[i];
        const TilePixel& e = exact[i];
        if (t.hit && t.level != 0) {
            return Error("tile comparison: pixel " + std::to_string(i) + " hit a cell of level " +
                         std::to_string(t.level) + ", not a voxel (run every pass)");
        }
        c.exactHits += e.hit;
        c.tileHits += t.hit;
        c.samples += t.samples;
        if (t.hit && e.hit) {
            (t.cell == e.cell ? c.sameVoxel : c.differentVoxel) += 1;
        } else if (e.hit) {
            c.missedSurface += 1;
            c.deadEnds += t.deadEnd;
        } else if (t.hit) {
            c.falseHit += 1;
        }
    }
    return c;
}

}  // namespace luxel::octree
