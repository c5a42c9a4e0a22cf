// MagicaVoxel .vox reader: chunks (vox_chunks.h), the scene graph (vox_scene_graph.h) and
// materials (vox_materials.h) composed into one world. Every size and offset is checked against
// the bytes that are actually there before it is used; nothing is allocated from an unchecked
// number.
#include "luxel/voxel/vox_import.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "luxel/core/file_io.h"
#include "luxel/core/memory.h"
#include "luxel/voxel/texture_set.h"
#include "voxel/vox_chunks.h"
#include "voxel/vox_materials.h"
#include "voxel/vox_scene_graph.h"

namespace luxel::voxel {
namespace {

using namespace vox;

// A failure about the file as a whole (no byte offset in the message).
constexpr std::size_t kNoOffset = static_cast<std::size_t>(-1);

// Most voxel writes one file may cause (instancing multiplies a model's voxels).
constexpr std::uint64_t kMaxPlacedVoxels = std::uint64_t{1} << 30;

struct Model {
    Int3 size;               // in vox axes (z up)
    std::size_t voxelsAt;    // offset of the first voxel record
    std::int32_t count = 0;  // number of voxel records
};

// What the chunks that luxel does not use were for, for the warning.
const char* ignoredChunkMeaning(const std::string& id) {
    if (id == "rOBJ") return "render settings";
    if (id == "rCAM") return "cameras; luxel frames the model itself";
    if (id == "NOTE") return "palette notes";
    if (id == "IMAP") return "palette display order";
    if (id == "MATT") return "old-style materials";
    return nullptr;
}

class Reader {
  public:
    Reader(Bytes bytes, const std::string& name, const VoxOptions& options)
        : b_(bytes), name_(name), options_(options) {}

    VoxImport read() {
        palette_ = defaultVoxPalette();
        for (const Chunk& c : readChunks(b_)) readChunk(c);
        if (pendingSize_) {
            throw VoxFailure{pendingAt_, "SIZE chunk is not followed by an XYZI chunk"};
        }
        if (models_.empty()) throw VoxFailure{8, "no model: the file has no SIZE and XYZI chunks"};
        return build();
    }

  private:
    void readChunk(const Chunk& c) {
        const std::size_t content = c.content;
        if (c.id == "SIZE") {
            if (pendingSize_)
                throw VoxFailure{pendingAt_, "SIZE chunk is not followed by an XYZI chunk"};
            if (c.size < 12) tooSmall(c, 12);
            const char* axis[3] = {"x", "y", "z"};
            for (int a = 0; a < 3; ++a) {
                pending_[a] = readI32(b_, content + 4 * a);
                if (pending_[a] < 1 || pending_[a] > kMaxVoxModelSide) {
                    throw VoxFailure{content + 4 * a, "SIZE " + std::string(axis[a]) + " = " +
                                                          std::to_string(pending_[a]) +
                                                          " is invalid: each side must be in 1.." +
                                                          std::to_string(kMaxVoxModelSide)};
                }
            }
            pendingSize_ = true;
            pendingAt_ = c.at;
        } else if (c.id == "XYZI") {
            readVoxels(c);
        } else if (c.id == "RGBA") {
            if (c.size < 1024) tooSmall(c, 1024);
            // Entry i of the chunk is colour index i + 1 (index 0 means empty).
            for (int i = 0; i < 255; ++i) {
                const std::size_t p = content + 4 * static_cast<std::size_t>(i);
                palette_[i + 1] = {b_[p], b_[p + 1], b_[p + 2], b_[p + 3]};
            }
        } else if (c.id == "PACK") {
            if (c.size < 4) tooSmall(c, 4);
            const std::int32_t models = readI32(b_, content);
            if (models < 1) {
                throw VoxFailure{content,
                                 "PACK chunk claims " + std::to_string(models) + " models"};
            }
        } else if (c.id == "nTRN") {
            graph_.addTransform(b_, c);
        } else if (c.id == "nGRP") {
            graph_.addGroup(b_, c);
        } else if (c.id == "nSHP") {
            graph_.addShape(b_, c);
        } else if (c.id == "LAYR") {
            graph_.addLayer(b_, c);
        } else if (c.id == "MATL") {
            FieldReader r(b_, c);
            const int id = r.i32("material id");
            Dict d = r.dict("material properties");
            if (id >= 1 && id <= 255) {
                matl_[id] = std::move(d);
            } else if (id != 0) {  // MagicaVoxel writes a material 0 for the empty index
                warn("MATL " + std::to_string(id) + " at byte " + std::to_string(c.at) +
                     ": not a colour index (1..255); ignored");
            }
        } else {
            ignoredChunk(c);
        }
    }

    void ignoredChunk(const Chunk& c) {
        if (std::find(ignoredIds_.begin(), ignoredIds_.end(), c.id) != ignoredIds_.end()) return;
        ignoredIds_.push_back(c.id);
        if (const char* meaning = ignoredChunkMeaning(c.id)) {
            warn("chunk " + c.id + " (" + meaning + ") ignored");
        } else {
            warn("unknown chunk '" + c.id + "' at byte " + std::to_string(c.at) + " ignored");
        }
    }

    void readVoxels(const Chunk& c) {
        if (!pendingSize_) throw VoxFailure{c.at, "XYZI chunk without a preceding SIZE chunk"};
        if (c.size < 4) tooSmall(c, 4);
        const std::int32_t count = readI32(b_, c.content);
        if (count < 0) {
            throw VoxFailure{c.content, "XYZI chunk claims a negative number of voxels (" +
                                            std::to_string(count) + ")"};
        }
        if (static_cast<std::uint64_t>(count) * 4 > c.size - 4) {
            throw VoxFailure{c.content, "XYZI chunk claims " + std::to_string(count) +
                                            " voxels but holds " + std::to_string(c.size - 4) +
                                            " bytes"};
        }
        const Int3 s = pending_;
        for (std::int32_t i = 0; i < count; ++i) {
            const std::size_t v = c.content + 4 + 4 * static_cast<std::size_t>(i);
            if (b_[v] >= s.x || b_[v + 1] >= s.y || b_[v + 2] >= s.z) {
                throw VoxFailure{v, "voxel " + std::to_string(i) + " at (" + std::to_string(b_[v]) +
                                        ", " + std::to_string(b_[v + 1]) + ", " +
                                        std::to_string(b_[v + 2]) + ") is outside the model size " +
                                        std::to_string(s.x) + "x" + std::to_string(s.y) + "x" +
                                        std::to_string(s.z)};
            }
        }
        models_.push_back({s, c.content + 4, count});
        pendingSize_ = false;
    }

    [[noreturn]] void tooSmall(const Chunk& c, int needed) const {
        throw VoxFailure{c.at + 4, c.id + " chunk holds " + std::to_string(c.size) +
                                       " bytes, needs at least " + std::to_string(needed)};
    }

    void warn(const std::string& message) { warnings_.push_back(name_ + ": " + message); }

    // Where the models go: the scene graph's placements, or (without one) the models side by side.
    std::vector<Placement> placements() {
        const int modelCount = static_cast<int>(models_.size());
        if (!graph_.empty()) return graph_.place(options_.frame, modelCount);
        std::vector<Placement> out;
        std::int64_t x = 0;
        for (int m = 0; m < modelCount; ++m) {
            const Int3 s = models_[m].size;
            Placement p{m, {}};
            p.transform.translation = {x + s.x / 2, s.y / 2, s.z / 2};
            out.push_back(p);
            x += s.x;
        }
        if (modelCount > 1) {
            warn(std::to_string(modelCount) +
                 " models and no scene graph (nTRN/nGRP/nSHP): laid side by side along x");
        }
        return out;
    }

    void frameWarnings() {
        const int frames = graph_.frameCount();
        if (frames <= 1 && options_.frame > 0) {
            warn("frame " + std::to_string(options_.frame) +
                 " asked for, but the file has no animation; showing its only frame");
        } else if (options_.frame >= frames) {
            warn("frame " + std::to_string(options_.frame) + " is past the last keyframe (" +
                 std::to_string(frames - 1) + "); the last keyframes hold");
        }
    }

    // The cell that voxel v of a placed model lands on (MagicaVoxel's pivot: floor(size / 2)).
    static Int3L cellOf(const Placement& p, const Int3& size, Int3L v) {
        for (int a = 0; a < 3; ++a) v[a] -= size[a] / 2;
        const Int3L r = p.transform.rotation.apply(v);
        return {r[0] + p.transform.translation[0], r[1] + p.transform.translation[1],
                r[2] + p.transform.translation[2]};
    }

    VoxImport build() {
        frameWarnings();
        const std::vector<Placement> placed = placements();
        // Colour use and the bounds of the placed models.
        std::array<std::uint64_t, 256> used{};
        Int3L lo{INT64_MAX, INT64_MAX, INT64_MAX}, hi{INT64_MIN, INT64_MIN, INT64_MIN};
        std::uint64_t writes = 0;
        for (const Placement& p : placed) {
            const Model& m = models_[p.model];
            for (int corner = 0; corner < 8; ++corner) {
                const Int3L v{corner & 1 ? m.size.x - 1 : 0, corner & 2 ? m.size.y - 1 : 0,
                              corner & 4 ? m.size.z - 1 : 0};
                const Int3L c = cellOf(p, m.size, v);
                for (int a = 0; a < 3; ++a) {
                    lo[a] = std::min(lo[a], c[a]);
                    hi[a] = std::max(hi[a], c[a] + 1);
                }
            }
            writes += static_cast<std::uint64_t>(m.count);
            if (writes > kMaxPlacedVoxels) {
                throw VoxFailure{8, "the scene graph places more than " +
                                        std::to_string(kMaxPlacedVoxels) + " voxels"};
            }
            for (std::int32_t i = 0; i < m.count; ++i)
                ++used[b_[m.voxelsAt + 4 * std::size_t(i) + 3]];
        }
        if (placed.empty()) {
            warn("every model is hidden; the world is empty");
            lo = {0, 0, 0};
            hi = {1, 1, 1};
        }
        FeatureWarnings features;
        PaletteMapping mapping = mapPalette(palette_, matl_, used, features);
        std::vector<std::string> lines;
        features.lines(lines);
        for (const std::string& line : lines) warn(line);

        const Int3L span{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
        checkSpan(span, lo);
        // vox (x, y, z) -> luxel (x, z, y)
        const Int3 size{int(span[0]), int(span[2]), int(span[1])};
        Result<VoxelWorld> created = VoxelWorld::create(size, options_.chunkSize);
        if (!created) throw VoxFailure{kNoOffset, created.error().message()};
        VoxImport out{std::move(created).value(), {}, {}, 1, 0, 0, {0, 0, 0}};
        for (const Placement& p : placed) {
            const Model& m = models_[p.model];
            for (std::int32_t i = 0; i < m.count; ++i) {
                const std::size_t v = m.voxelsAt + 4 * static_cast<std::size_t>(i);
                const std::uint8_t index = b_[v + 3];
                const int slot = mapping.slot[index];
                if (index == 0 || slot == PaletteMapping::kSkip) continue;
                Voxel c = palette_[index];
                c.a = slot >= 0 && options_.materials ? alphaForSlot(slot) : kPlainBlockAlpha;
                const Int3L cell = cellOf(p, m.size, {b_[v], b_[v + 1], b_[v + 2]});
                out.world.set(int(cell[0] - lo[0]), int(cell[2] - lo[2]), int(cell[1] - lo[1]), c);
            }
        }
        out.world.refreshEmptySpace();
        if (options_.materials) out.materials = std::move(mapping.materials);
        out.warnings = std::move(warnings_);
        out.frameCount = graph_.frameCount();
        out.modelCount = static_cast<int>(models_.size());
        out.placedCount = static_cast<int>(placed.size());
        out.voxOrigin = lo;
        return out;
    }

    // Refuses placements that no world can hold, with the size and the memory it would need.
    void checkSpan(const Int3L& span, const Int3L& lo) const {
        if (span[0] <= kMaxWorldSide && span[1] <= kMaxWorldSide && span[2] <= kMaxWorldSide) {
            const std::uint64_t bytes = VoxelWorld::bytesFor(
                {int(span[0]), int(span[2]), int(span[1])}, options_.chunkSize);
            if (options_.maxWorldBytes == 0 || bytes <= options_.maxWorldBytes) return;
            throw VoxFailure{kNoOffset, "the placed models span " + std::to_string(span[0]) + "x" +
                                            std::to_string(span[1]) + "x" +
                                            std::to_string(span[2]) + " voxels, a world of " +
                                            formatBytes(bytes) + "; the limit here is " +
                                            formatBytes(options_.maxWorldBytes)};
        }
        // A dense world of that span: 4 bytes a voxel (VoxelWorld::bytesFor adds a little).
        const double bytes = double(span[0]) * double(span[1]) * double(span[2]) * sizeof(Voxel);
        const std::string need = bytes < 1.8e19 ? formatBytes(static_cast<std::uint64_t>(bytes))
                                                : std::string("more than 16 EiB");
        throw VoxFailure{8, "the placed models span " + std::to_string(span[0]) + "x" +
                                std::to_string(span[1]) + "x" + std::to_string(span[2]) +
                                " voxels (vox axes, from (" + std::to_string(lo[0]) + ", " +
                                std::to_string(lo[1]) + ", " + std::to_string(lo[2]) +
                                ")): a world is at most " + std::to_string(kMaxWorldSide) +
                                " per side, and this one would need " + need};
    }

    Bytes b_;
    const std::string& name_;
    VoxOptions options_;
    std::array<Voxel, 256> palette_{};
    std::vector<Model> models_;
    bool pendingSize_ = false;
    std::size_t pendingAt_ = 0;
    Int3 pending_;
    SceneGraph graph_;
    std::map<int, Dict> matl_;
    std::vector<std::string> ignoredIds_;
    std::vector<std::string> warnings_;
};

}  // namespace

const std::array<Voxel, 256>& defaultVoxPalette() {
    // Generated rather than tabulated; it follows the layout of MagicaVoxel's default palette:
    // indices 1..215 are the 6x6x6 colour cube (components FF, CC, 99, 66, 33, 00; blue fastest,
    // black left out), then ten-step ramps of red, green, blue and grey (EE, DD, BB, AA, 88, 77,
    // 55, 44, 22, 11).
    static const std::array<Voxel, 256> palette = [] {
        std::array<Voxel, 256> p{};
        int i = 1;
        for (int r = 5; r >= 0; --r) {
            for (int g = 5; g >= 0; --g) {
                for (int b = 5; b >= 0; --b) {
                    if (r == 0 && g == 0 && b == 0) continue;
                    p[i++] = {static_cast<std::uint8_t>(r * 51), static_cast<std::uint8_t>(g * 51),
                              static_cast<std::uint8_t>(b * 51), 255};
                }
            }
        }
        const std::uint8_t ramp[10] = {0xee, 0xdd, 0xbb, 0xaa, 0x88, 0x77, 0x55, 0x44, 0x22, 0x11};
        for (int channel = 0; channel < 4; ++channel) {
            for (std::uint8_t v : ramp) {
                Voxel c{0, 0, 0, 255};
                if (channel == 0 || channel == 3) c.r = v;
                if (channel == 1 || channel == 3) c.g = v;
                if (channel == 2 || channel == 3) c.b = v;
                p[i++] = c;
            }
        }
        return p;  // i == 255: entry 255 is the last ramp step
    }();
    return palette;
}

Result<VoxImport> readVox(std::span<const std::uint8_t> bytes, const std::string& name,
                          const VoxOptions& options) {
    if (bytes.size() > kMaxVoxFileBytes) {
        return Error(name + ": " + std::to_string(bytes.size()) +
                     " bytes is larger than the 256 MiB limit for .vox files");
    }
    try {
        return Reader(bytes, name, options).read();
    } catch (const VoxFailure& f) {
        if (f.at == kNoOffset) return Error(name + ": " + f.message);
        return Error(name + ": byte " + std::to_string(f.at) + ": " + f.message);
    }
}

Result<VoxImport> readVoxFile(const std::string& path, const VoxOptions& options) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return Error(path + ": cannot read: " + ec.message());
    if (size > kMaxVoxFileBytes) {
        return Error(path + ": " + std::to_string(size) +
                     " bytes is larger than the 256 MiB limit for .vox files");
    }
    Result<std::string> bytes = readFileBytes(path, ".vox file", kMaxVoxFileBytes);
    if (!bytes) return bytes.error();
    return readVox(std::span(reinterpret_cast<const std::uint8_t*>(bytes->data()), bytes->size()),
                   path, options);
}

Result<VoxelWorld> parseVox(std::span<const std::uint8_t> bytes, const std::string& name,
                            int chunkSize) {
    Result<VoxImport> r = readVox(bytes, name, {chunkSize, 0, false});
    if (!r) return r.error();
    return std::move(r->world);
}

Result<VoxelWorld> loadVox(const std::string& path, int chunkSize) {
    Result<VoxImport> r = readVoxFile(path, {chunkSize, 0, false});
    if (!r) return r.error();
    return std::move(r->world);
}

}  // namespace luxel::voxel
