// MagicaVoxel .vox reader and writer (format: ephtracy/voxel-model,
// MagicaVoxel-file-format-vox.txt). Every size and offset is checked against the bytes that are
// actually there before it is used; nothing is allocated from an unchecked number.
#include "luxel/voxel/vox_import.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <unordered_map>

#include "luxel/core/file_io.h"

namespace luxel::voxel {
namespace {

constexpr int kMaxVoxModelSide = 256;  // coordinates in XYZI are single bytes

std::int32_t readI32(std::span<const std::uint8_t> b, std::size_t at) {
    const std::uint32_t u = static_cast<std::uint32_t>(b[at]) |
                            (static_cast<std::uint32_t>(b[at + 1]) << 8) |
                            (static_cast<std::uint32_t>(b[at + 2]) << 16) |
                            (static_cast<std::uint32_t>(b[at + 3]) << 24);
    return static_cast<std::int32_t>(u);
}

// A chunk id for messages: printable characters kept, anything else as '?'.
std::string chunkId(std::span<const std::uint8_t> b, std::size_t at) {
    std::string id(4, '?');
    for (int i = 0; i < 4; ++i) {
        const std::uint8_t c = b[at + i];
        if (c >= 32 && c < 127) id[i] = static_cast<char>(c);
    }
    return id;
}

bool idIs(std::span<const std::uint8_t> b, std::size_t at, const char* id) {
    return std::memcmp(b.data() + at, id, 4) == 0;
}

struct Model {
    Int3 size;               // in vox axes (z up)
    std::size_t voxelsAt;    // offset of the first voxel record
    std::int32_t count = 0;  // number of voxel records
};

class Parser {
  public:
    Parser(std::span<const std::uint8_t> bytes, const std::string& name) : b_(bytes), name_(name) {}

    Error fail(std::size_t at, const std::string& message) const {
        return Error(name_ + ": byte " + std::to_string(at) + ": " + message);
    }

    Result<VoxelWorld> parse(int chunkSize) {
        const std::size_t n = b_.size();
        if (n < 8) {
            return fail(
                0, "file is truncated: " + std::to_string(n) + " bytes, a .vox header needs 8");
        }
        if (!idIs(b_, 0, "VOX ")) return fail(0, "not a MagicaVoxel file: no \"VOX \" magic");
        const std::int32_t version = readI32(b_, 4);
        if (version != 150 && version != 200) {
            return fail(4, "unsupported .vox version " + std::to_string(version) +
                               " (expected 150 or 200)");
        }
        if (n - 8 < 12) return fail(8, "file is truncated: no MAIN chunk header");
        if (!idIs(b_, 8, "MAIN")) {
            return fail(8, "expected the MAIN chunk, found '" + chunkId(b_, 8) + "'");
        }
        std::size_t contentSize = 0, childrenSize = 0;
        if (Status s = chunkSizes(8, n, contentSize, childrenSize); !s) return s.error();
        const std::size_t end = 20 + contentSize + childrenSize;
        palette_ = defaultVoxPalette();

        bool pendingSize = false;
        std::size_t pendingAt = 0;
        Int3 pending;
        for (std::size_t at = 20 + contentSize; at < end;) {
            if (end - at < 12) {
                return fail(at, "truncated chunk header: " + std::to_string(end - at) +
                                    " bytes left in MAIN, a chunk header needs 12");
            }
            std::size_t size = 0, children = 0;
            if (Status s = chunkSizes(at, end, size, children); !s) return s.error();
            const std::size_t content = at + 12;
            if (idIs(b_, at, "SIZE")) {
                if (pendingSize) {
                    return fail(pendingAt, "SIZE chunk is not followed by an XYZI chunk");
                }
                if (size < 12) return tooSmall(at, "SIZE", size, 12);
                const char* axis[3] = {"x", "y", "z"};
                for (int a = 0; a < 3; ++a) {
                    pending[a] = readI32(b_, content + 4 * a);
                    if (pending[a] < 1 || pending[a] > kMaxVoxModelSide) {
                        return fail(content + 4 * a, "SIZE " + std::string(axis[a]) + " = " +
                                                         std::to_string(pending[a]) +
                                                         " is invalid: each side must be in 1.." +
                                                         std::to_string(kMaxVoxModelSide));
                    }
                }
                pendingSize = true;
                pendingAt = at;
            } else if (idIs(b_, at, "XYZI")) {
                if (!pendingSize) return fail(at, "XYZI chunk without a preceding SIZE chunk");
                if (size < 4) return tooSmall(at, "XYZI", size, 4);
                const std::int32_t count = readI32(b_, content);
                if (count < 0) {
                    return fail(content, "XYZI chunk claims a negative number of voxels (" +
                                             std::to_string(count) + ")");
                }
                if (static_cast<std::uint64_t>(count) * 4 > size - 4) {
                    return fail(content, "XYZI chunk claims " + std::to_string(count) +
                                             " voxels but holds " + std::to_string(size - 4) +
                                             " bytes");
                }
                for (std::int32_t i = 0; i < count; ++i) {
                    const std::size_t v = content + 4 + 4 * static_cast<std::size_t>(i);
                    if (b_[v] >= pending.x || b_[v + 1] >= pending.y || b_[v + 2] >= pending.z) {
                        return fail(
                            v, "voxel " + std::to_string(i) + " at (" + std::to_string(b_[v]) +
                                   ", " + std::to_string(b_[v + 1]) + ", " +
                                   std::to_string(b_[v + 2]) + ") is outside the model size " +
                                   std::to_string(pending.x) + "x" + std::to_string(pending.y) +
                                   "x" + std::to_string(pending.z));
                    }
                }
                models_.push_back({pending, content + 4, count});
                pendingSize = false;
            } else if (idIs(b_, at, "RGBA")) {
                if (size < 1024) return tooSmall(at, "RGBA", size, 1024);
                // Entry i of the chunk is colour index i + 1 (index 0 means empty).
                for (int i = 0; i < 255; ++i) {
                    const std::size_t p = content + 4 * static_cast<std::size_t>(i);
                    palette_[i + 1] = {b_[p], b_[p + 1], b_[p + 2], b_[p + 3]};
                }
            } else if (idIs(b_, at, "PACK")) {
                if (size < 4) return tooSmall(at, "PACK", size, 4);
                const std::int32_t models = readI32(b_, content);
                if (models < 1) {
                    return fail(content, "PACK chunk claims " + std::to_string(models) + " models");
                }
            }
            // Anything else (nTRN, nGRP, nSHP, MATL, LAYR, rOBJ, rCAM, IMAP, NOTE, ...) is skipped.
            at = content + size + children;
        }
        if (pendingSize) return fail(pendingAt, "SIZE chunk is not followed by an XYZI chunk");
        if (models_.empty()) return fail(8, "no model: the file has no SIZE and XYZI chunks");
        return build(chunkSize);
    }

  private:
    // Reads the content and children sizes of the chunk at `at`; both must fit before `end`.
    Status chunkSizes(std::size_t at, std::size_t end, std::size_t& content,
                      std::size_t& children) const {
        const std::string id = chunkId(b_, at);
        const std::int32_t n = readI32(b_, at + 4), m = readI32(b_, at + 8);
        if (n < 0) {
            return fail(at + 4,
                        id + " chunk has a negative content size (" + std::to_string(n) + ")");
        }
        if (m < 0) {
            return fail(at + 8,
                        id + " chunk has a negative children size (" + std::to_string(m) + ")");
        }
        const std::uint64_t left = end - (at + 12);
        const std::uint64_t claimed = static_cast<std::uint64_t>(n) + static_cast<std::uint64_t>(m);
        if (claimed > left) {
            return fail(at + 4, id + " chunk claims " + std::to_string(claimed) +
                                    " bytes but only " + std::to_string(left) + " remain");
        }
        content = static_cast<std::size_t>(n);
        children = static_cast<std::size_t>(m);
        return Ok{};
    }

    Error tooSmall(std::size_t at, const char* id, std::size_t size, int needed) const {
        return fail(at + 4, std::string(id) + " chunk holds " + std::to_string(size) +
                                " bytes, needs at least " + std::to_string(needed));
    }

    Result<VoxelWorld> build(int chunkSize) {
        // Models side by side along luxel x; vox z (up) is luxel y, vox y is luxel z.
        std::int64_t width = 0;
        int height = 1, depth = 1;
        for (const Model& m : models_) {
            width += m.size.x;
            height = std::max(height, m.size.z);
            depth = std::max(depth, m.size.y);
            if (width > kMaxWorldSide) {
                return fail(8, "the " + std::to_string(models_.size()) +
                                   "+ models side by side are wider than " +
                                   std::to_string(kMaxWorldSide) + " voxels");
            }
        }
        Result<VoxelWorld> created =
            VoxelWorld::create({static_cast<int>(width), height, depth}, chunkSize);
        if (!created) return Error(name_ + ": " + created.error().message());
        VoxelWorld world = std::move(created).value();
        int offset = 0;
        for (const Model& m : models_) {
            for (std::int32_t i = 0; i < m.count; ++i) {
                const std::size_t v = m.voxelsAt + 4 * static_cast<std::size_t>(i);
                const std::uint8_t index = b_[v + 3];
                if (index == 0) continue;
                Voxel c = palette_[index];
                c.a = 255;  // a listed voxel is a solid plain block (alpha 1..254 are textures)
                world.set(offset + b_[v], b_[v + 2], b_[v + 1], c);
            }
            offset += m.size.x;
        }
        world.refreshEmptySpace();
        return world;
    }

    std::span<const std::uint8_t> b_;
    const std::string& name_;
    std::array<Voxel, 256> palette_{};
    std::vector<Model> models_;
};

std::uint32_t pack(Voxel v) {
    return static_cast<std::uint32_t>(v.r) | (static_cast<std::uint32_t>(v.g) << 8) |
           (static_cast<std::uint32_t>(v.b) << 16) | (static_cast<std::uint32_t>(v.a) << 24);
}
Voxel unpack(std::uint32_t c) {
    return {static_cast<std::uint8_t>(c), static_cast<std::uint8_t>(c >> 8),
            static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>(c >> 24)};
}

void putI32(std::vector<std::uint8_t>& out, std::int64_t v) {
    const auto u = static_cast<std::uint32_t>(v);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(u >> (8 * i)));
}
void putId(std::vector<std::uint8_t>& out, const char* id) {
    out.insert(out.end(), id, id + 4);
}

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

Result<VoxelWorld> parseVox(std::span<const std::uint8_t> bytes, const std::string& name,
                            int chunkSize) {
    if (bytes.size() > kMaxVoxFileBytes) {
        return Error(name + ": " + std::to_string(bytes.size()) +
                     " bytes is larger than the 256 MiB limit for .vox files");
    }
    return Parser(bytes, name).parse(chunkSize);
}

Result<VoxelWorld> loadVox(const std::string& path, int chunkSize) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return Error(path + ": cannot read: " + ec.message());
    if (size > kMaxVoxFileBytes) {
        return Error(path + ": " + std::to_string(size) +
                     " bytes is larger than the 256 MiB limit for .vox files");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error(path + ": cannot open for reading");
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) {
        return Error(path + ": read " + std::to_string(in.gcount()) + " of " +
                     std::to_string(size) + " bytes");
    }
    return parseVox(bytes, path, chunkSize);
}

Result<std::vector<std::uint8_t>> encodeVox(const VoxelWorld& world) {
    const Int3 s = world.size();
    if (s.x > kMaxVoxModelSide || s.y > kMaxVoxModelSide || s.z > kMaxVoxModelSide) {
        return Error("a " + std::to_string(s.x) + "x" + std::to_string(s.y) + "x" +
                     std::to_string(s.z) + " world does not fit one .vox model (at most " +
                     std::to_string(kMaxVoxModelSide) + " per side)");
    }
    // Colour histogram of the solid voxels.
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
    const std::size_t kept = std::min<std::size_t>(colours.size(), 255);
    std::unordered_map<std::uint32_t, std::uint8_t> indexOf;
    for (std::size_t i = 0; i < kept; ++i) {
        indexOf[colours[i].first] = static_cast<std::uint8_t>(i + 1);
    }
    for (std::size_t i = kept; i < colours.size(); ++i) {
        const Voxel c = unpack(colours[i].first);
        int best = 0;
        std::int64_t bestDistance = INT64_MAX;
        for (std::size_t k = 0; k < kept; ++k) {
            const Voxel p = unpack(colours[k].first);
            const std::int64_t dr = c.r - p.r, dg = c.g - p.g, db = c.b - p.b, da = c.a - p.a;
            const std::int64_t distance = dr * dr + dg * dg + db * db + da * da;
            if (distance < bestDistance) {
                bestDistance = distance;
                best = static_cast<int>(k);
            }
        }
        indexOf[colours[i].first] = static_cast<std::uint8_t>(best + 1);
    }

    const std::uint64_t count = world.solidCount();
    const std::uint64_t xyziBytes = 4 + 4 * count;
    const std::uint64_t children = (12 + 12) + (12 + xyziBytes) + (12 + 1024);
    std::vector<std::uint8_t> out;
    out.reserve(static_cast<std::size_t>(20 + children));
    putId(out, "VOX ");
    putI32(out, 150);
    putId(out, "MAIN");
    putI32(out, 0);
    putI32(out, static_cast<std::int64_t>(children));
    putId(out, "SIZE");
    putI32(out, 12);
    putI32(out, 0);
    putI32(out, s.x);  // vox x, y, z = luxel x, z, y (vox is z-up)
    putI32(out, s.z);
    putI32(out, s.y);
    putId(out, "XYZI");
    putI32(out, static_cast<std::int64_t>(xyziBytes));
    putI32(out, 0);
    putI32(out, static_cast<std::int64_t>(count));
    for (int z = 0; z < s.z; ++z) {
        for (int y = 0; y < s.y; ++y) {
            for (int x = 0; x < s.x; ++x) {
                const Voxel v = world.get(x, y, z);
                if (!v.solid()) continue;
                out.push_back(static_cast<std::uint8_t>(x));
                out.push_back(static_cast<std::uint8_t>(z));
                out.push_back(static_cast<std::uint8_t>(y));
                out.push_back(indexOf[pack(v)]);
            }
        }
    }
    putId(out, "RGBA");
    putI32(out, 1024);
    putI32(out, 0);
    for (int i = 0; i < 256; ++i) {
        const Voxel c = i < static_cast<int>(kept) ? unpack(colours[i].first) : Voxel{};
        out.insert(out.end(), {c.r, c.g, c.b, c.a});
    }
    return out;
}

Status saveVox(const VoxelWorld& world, const std::string& path) {
    Result<std::vector<std::uint8_t>> bytes = encodeVox(world);
    if (!bytes) return Error(path + ": " + bytes.error().message());
    return writeFileAtomically(
        path, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()),
        "vox file");
}

}  // namespace luxel::voxel
