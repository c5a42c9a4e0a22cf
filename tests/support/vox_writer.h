// Builds MagicaVoxel .vox byte streams for tests, chunk by chunk (ephtracy/voxel-model,
// MagicaVoxel-file-format-vox.txt and -vox-extension.txt), so each test states the file it reads.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace luxel::test::vox {

using Bytes = std::vector<std::uint8_t>;
using Dict = std::vector<std::pair<std::string, std::string>>;
using Voxel4 = std::array<std::uint8_t, 4>;  // x, y, z, colour index (vox axes, z up)

inline void putI32(Bytes& b, std::int64_t v) {
    const auto u = static_cast<std::uint32_t>(v);
    for (int i = 0; i < 4; ++i) b.push_back(static_cast<std::uint8_t>(u >> (8 * i)));
}

inline Bytes cat(std::initializer_list<Bytes> parts) {
    Bytes b;
    for (const Bytes& p : parts) b.insert(b.end(), p.begin(), p.end());
    return b;
}

inline Bytes ints(std::initializer_list<std::int64_t> values) {
    Bytes b;
    for (std::int64_t v : values) putI32(b, v);
    return b;
}

// A chunk: id, content size, children size, then content and children.
inline Bytes chunk(const char* id, const Bytes& content, const Bytes& children = {}) {
    Bytes b(id, id + 4);
    putI32(b, static_cast<std::int64_t>(content.size()));
    putI32(b, static_cast<std::int64_t>(children.size()));
    b.insert(b.end(), content.begin(), content.end());
    b.insert(b.end(), children.begin(), children.end());
    return b;
}

inline Bytes string(const std::string& s) {
    Bytes b;
    putI32(b, static_cast<std::int64_t>(s.size()));
    for (char c : s) b.push_back(static_cast<std::uint8_t>(c));
    return b;
}

inline Bytes dict(const Dict& d) {
    Bytes b;
    putI32(b, static_cast<std::int64_t>(d.size()));
    for (const auto& [k, v] : d) b = cat({b, string(k), string(v)});
    return b;
}

inline Bytes file(const Bytes& mainChildren, std::int64_t version = 200) {
    Bytes b = {'V', 'O', 'X', ' '};
    putI32(b, version);
    return cat({b, chunk("MAIN", {}, mainChildren)});
}

// SIZE and XYZI of one model.
inline Bytes model(int sx, int sy, int sz, const std::vector<Voxel4>& voxels) {
    Bytes xyzi;
    putI32(xyzi, static_cast<std::int64_t>(voxels.size()));
    for (const Voxel4& v : voxels) xyzi.insert(xyzi.end(), v.begin(), v.end());
    return cat({chunk("SIZE", ints({sx, sy, sz})), chunk("XYZI", xyzi)});
}

// nTRN with one keyframe per entry of `frames` (each a DICT: _t, _r, _f).
inline Bytes transform(int id, int child, const std::vector<Dict>& frames = {{}}, int layer = -1,
                       const Dict& attributes = {}) {
    Bytes b = cat({ints({id}), dict(attributes),
                   ints({child, -1, layer, static_cast<std::int64_t>(frames.size())})});
    for (const Dict& f : frames) b = cat({b, dict(f)});
    return chunk("nTRN", b);
}

inline Bytes group(int id, const std::vector<int>& children, const Dict& attributes = {}) {
    Bytes b =
        cat({ints({id}), dict(attributes), ints({static_cast<std::int64_t>(children.size())})});
    for (int c : children) putI32(b, c);
    return chunk("nGRP", b);
}

// nSHP with (model id, frame) pairs; a frame < 0 writes no _f.
inline Bytes shape(int id, const std::vector<std::pair<int, int>>& models,
                   const Dict& attributes = {}) {
    Bytes b = cat({ints({id}), dict(attributes), ints({static_cast<std::int64_t>(models.size())})});
    for (const auto& [m, f] : models) {
        b = cat({b, ints({m}), dict(f < 0 ? Dict{} : Dict{{"_f", std::to_string(f)}})});
    }
    return chunk("nSHP", b);
}

inline Bytes layer(int id, bool hidden) {
    return chunk("LAYR",
                 cat({ints({id}), dict(hidden ? Dict{{"_hidden", "1"}} : Dict{}), ints({-1})}));
}

inline Bytes material(int id, const Dict& properties) {
    return chunk("MATL", cat({ints({id}), dict(properties)}));
}

// RGBA with `colours` (index -> r, g, b, a); other entries white and opaque.
inline Bytes palette(const std::vector<std::pair<int, Voxel4>>& colours) {
    Bytes b(1024, 255);
    for (const auto& [index, c] : colours) {
        for (int k = 0; k < 4; ++k) b[4 * (index - 1) + k] = c[k];
    }
    return chunk("RGBA", b);
}

}  // namespace luxel::test::vox
