// MagicaVoxel .vox writer: version 200, the world cut into models of at most 256 per side that a
// scene graph places back where they were, the palette and the materials (MATL).
#include <algorithm>
#include <string_view>
#include <unordered_map>

#include "luxel/core/file_io.h"
#include "luxel/voxel/texture_set.h"
#include "luxel/voxel/vox_import.h"
#include "voxel/vox_chunks.h"
#include "voxel/vox_materials.h"

namespace luxel::voxel {
namespace {

using Out = std::vector<std::uint8_t>;

std::uint32_t pack(Voxel v) {
    return static_cast<std::uint32_t>(v.r) | (static_cast<std::uint32_t>(v.g) << 8) |
           (static_cast<std::uint32_t>(v.b) << 16) | (static_cast<std::uint32_t>(v.a) << 24);
}
Voxel unpack(std::uint32_t c) {
    return {static_cast<std::uint8_t>(c), static_cast<std::uint8_t>(c >> 8),
            static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>(c >> 24)};
}

void putI32(Out& out, std::int64_t v) {
    const auto u = static_cast<std::uint32_t>(v);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(u >> (8 * i)));
}
void putString(Out& out, std::string_view s) {
    putI32(out, static_cast<std::int64_t>(s.size()));
    out.insert(out.end(), s.begin(), s.end());
}
void putDict(Out& out, const vox::Dict& d) {
    putI32(out, static_cast<std::int64_t>(d.size()));
    for (const auto& [k, v] : d) {
        putString(out, k);
        putString(out, v);
    }
}
void putChunk(Out& out, const char* id, const Out& content) {
    out.insert(out.end(), id, id + 4);
    putI32(out, static_cast<std::int64_t>(content.size()));
    putI32(out, 0);
    out.insert(out.end(), content.begin(), content.end());
}

// The palette: colour indices for every (colour, material byte) of the world's solid voxels.
struct Palette {
    std::vector<std::uint32_t> kept;  // index i + 1 holds kept[i]
    std::unordered_map<std::uint32_t, std::uint8_t> indexOf;
    std::size_t merged = 0;  // distinct colours written as their nearest kept one
};

Palette buildPalette(const VoxelWorld& world) {
    const Int3 s = world.size();
    std::unordered_map<std::uint32_t, std::uint64_t> histogram;
    for (int z = 0; z < s.z; ++z) {
        for (int y = 0; y < s.y; ++y) {
            for (int x = 0; x < s.x; ++x) {
                const Voxel v = world.get(x, y, z);
                if (v.solid()) ++histogram[pack(v)];
            }
        }
    }
    std::vector<std::pair<std::uint32_t, std::uint64_t>> colours(histogram.begin(),
                                                                 histogram.end());
    // Most frequent first; ties by value so the output is deterministic.
    std::sort(colours.begin(), colours.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    Palette p;
    const std::size_t kept = std::min<std::size_t>(colours.size(), 255);
    for (std::size_t i = 0; i < kept; ++i) {
        p.kept.push_back(colours[i].first);
        p.indexOf[colours[i].first] = static_cast<std::uint8_t>(i + 1);
    }
    for (std::size_t i = kept; i < colours.size(); ++i) {
        const Voxel c = unpack(colours[i].first);
        std::size_t best = 0;
        std::int64_t bestDistance = INT64_MAX;
        for (std::size_t k = 0; k < kept; ++k) {
            const Voxel q = unpack(p.kept[k]);
            const std::int64_t dr = c.r - q.r, dg = c.g - q.g, db = c.b - q.b, da = c.a - q.a;
            const std::int64_t distance = dr * dr + dg * dg + db * db + da * da;
            if (distance < bestDistance) {
                bestDistance = distance;
                best = k;
            }
        }
        p.indexOf[colours[i].first] = static_cast<std::uint8_t>(best + 1);
        ++p.merged;
    }
    return p;
}

// One model: a tile of at most 256 per side, in vox axes (z up).
struct Tile {
    std::array<int, 3> origin{}, size{};
    Out voxels;  // x, y, z, colour index records
};

}  // namespace

Result<VoxExport> exportVox(const VoxelWorld& world, const MaterialTable* materials) {
    VoxExport result;
    const Int3 s = world.size();
    const std::array<int, 3> voxSize{s.x, s.z, s.y};  // vox (x, y, z) = luxel (x, z, y)
    const Palette palette = buildPalette(world);
    if (palette.merged > 0) {
        result.warnings.push_back(std::to_string(palette.merged) +
                                  " colours beyond the 255 of a .vox palette were written as "
                                  "the nearest kept colour");
    }

    // Tiles in vox axes; a tile holds the voxels of its 256^3 block.
    std::array<int, 3> tiles{};
    for (int a = 0; a < 3; ++a) tiles[a] = (voxSize[a] + kMaxVoxModelSide - 1) / kMaxVoxModelSide;
    const auto tileIndex = [&](int tx, int ty, int tz) {
        return (static_cast<std::size_t>(tz) * tiles[1] + ty) * tiles[0] + tx;
    };
    std::vector<Tile> grid(static_cast<std::size_t>(tiles[0]) * tiles[1] * tiles[2]);
    for (int tz = 0; tz < tiles[2]; ++tz) {
        for (int ty = 0; ty < tiles[1]; ++ty) {
            for (int tx = 0; tx < tiles[0]; ++tx) {
                Tile& t = grid[tileIndex(tx, ty, tz)];
                const std::array<int, 3> at{tx, ty, tz};
                for (int a = 0; a < 3; ++a) {
                    t.origin[a] = at[a] * kMaxVoxModelSide;
                    t.size[a] = std::min(kMaxVoxModelSide, voxSize[a] - t.origin[a]);
                }
            }
        }
    }
    for (int z = 0; z < s.z; ++z) {
        for (int y = 0; y < s.y; ++y) {
            for (int x = 0; x < s.x; ++x) {
                const Voxel v = world.get(x, y, z);
                if (!v.solid()) continue;
                const int vx = x, vy = z, vz = y;
                Tile& t = grid[tileIndex(vx / kMaxVoxModelSide, vy / kMaxVoxModelSide,
                                         vz / kMaxVoxModelSide)];
                t.voxels.insert(t.voxels.end(), {static_cast<std::uint8_t>(vx - t.origin[0]),
                                                 static_cast<std::uint8_t>(vy - t.origin[1]),
                                                 static_cast<std::uint8_t>(vz - t.origin[2]),
                                                 palette.indexOf.at(pack(v))});
            }
        }
    }
    // Empty tiles are left out, except the first and the last: the world spans the placed
    // models, so these two keep its size.
    std::vector<const Tile*> written;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        if (!grid[i].voxels.empty() || i == 0 || i + 1 == grid.size()) written.push_back(&grid[i]);
    }

    Out children;
    for (const Tile* t : written) {
        Out size;
        for (int a = 0; a < 3; ++a) putI32(size, t->size[a]);
        putChunk(children, "SIZE", size);
        Out xyzi;
        putI32(xyzi, static_cast<std::int64_t>(t->voxels.size() / 4));
        xyzi.insert(xyzi.end(), t->voxels.begin(), t->voxels.end());
        putChunk(children, "XYZI", xyzi);
    }
    // Scene graph: root transform 0 -> group 1 -> (transform 2k+2 -> shape 2k+3) per model. The
    // translation puts the model's pivot, floor(size / 2), where it was in the world.
    const int models = static_cast<int>(written.size());
    {
        Out root;
        putI32(root, 0);
        putDict(root, {});
        putI32(root, 1);
        putI32(root, -1);
        putI32(root, -1);
        putI32(root, 1);
        putDict(root, {});
        putChunk(children, "nTRN", root);
        Out group;
        putI32(group, 1);
        putDict(group, {});
        putI32(group, models);
        for (int k = 0; k < models; ++k) putI32(group, 2 * k + 2);
        putChunk(children, "nGRP", group);
    }
    for (int k = 0; k < models; ++k) {
        const Tile& t = *written[k];
        Out transform;
        putI32(transform, 2 * k + 2);
        putDict(transform, {});
        putI32(transform, 2 * k + 3);
        putI32(transform, -1);
        putI32(transform, 0);
        putI32(transform, 1);
        putDict(transform, {{"_t", std::to_string(t.origin[0] + t.size[0] / 2) + " " +
                                       std::to_string(t.origin[1] + t.size[1] / 2) + " " +
                                       std::to_string(t.origin[2] + t.size[2] / 2)}});
        putChunk(children, "nTRN", transform);
        Out shape;
        putI32(shape, 2 * k + 3);
        putDict(shape, {});
        putI32(shape, 1);
        putI32(shape, k);
        putDict(shape, {});
        putChunk(children, "nSHP", shape);
    }
    {
        Out layer;
        putI32(layer, 0);
        putDict(layer, {});
        putI32(layer, -1);
        putChunk(children, "LAYR", layer);
    }
    Out rgba;
    for (int i = 0; i < 256; ++i) {
        Voxel c = i < static_cast<int>(palette.kept.size()) ? unpack(palette.kept[i]) : Voxel{};
        c.a = 255;  // the material byte goes to MATL, not to palette alpha
        rgba.insert(rgba.end(), {c.r, c.g, c.b, c.a});
    }
    putChunk(children, "RGBA", rgba);
    bool texturesLost = false;
    for (std::size_t i = 0; i < palette.kept.size(); ++i) {
        const Voxel c = unpack(palette.kept[i]);
        const int slot = textureSlotOf(c);
        if (slot < 0) continue;
        if (!materials || !materials->hasSlot(slot)) {
            texturesLost = true;
            continue;
        }
        const Material& m = materials->forSlot(slot);
        if (!m.proceduralTexture) texturesLost = true;  // a texture image with a material
        Out matl;
        putI32(matl, static_cast<std::int64_t>(i + 1));
        putDict(matl, vox::matlFor(m, c));
        putChunk(children, "MATL", matl);
    }
    if (texturesLost) {
        result.warnings.push_back(
            "textured voxels are written as their colour (face images are not part of .vox)");
    }

    Out& out = result.bytes;
    out = {'V', 'O', 'X', ' '};
    putI32(out, 200);
    out.insert(out.end(), {'M', 'A', 'I', 'N'});
    putI32(out, 0);
    putI32(out, static_cast<std::int64_t>(children.size()));
    out.insert(out.end(), children.begin(), children.end());
    result.models = models;
    return result;
}

Result<std::vector<std::string>> writeVox(const VoxelWorld& world, const std::string& path,
                                          const MaterialTable* materials) {
    Result<VoxExport> encoded = exportVox(world, materials);
    if (!encoded) return Error(path + ": " + encoded.error().message());
    const std::vector<std::uint8_t>& bytes = encoded->bytes;
    if (Status s = writeFileAtomically(
            path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
            "vox file");
        !s) {
        return s.error();
    }
    return std::move(encoded->warnings);
}

Result<std::vector<std::uint8_t>> encodeVox(const VoxelWorld& world) {
    Result<VoxExport> r = exportVox(world);
    if (!r) return r.error();
    return std::move(r->bytes);
}

Status saveVox(const VoxelWorld& world, const std::string& path) {
    Result<std::vector<std::string>> r = writeVox(world, path);
    if (!r) return r.error();
    return Ok{};
}

}  // namespace luxel::voxel
