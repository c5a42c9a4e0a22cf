#include "voxel/vox_chunks.h"

#include <charconv>
#include <cmath>
#include <cstring>

namespace luxel::voxel::vox {
namespace {

std::string chunkId(Bytes b, std::size_t at) {
    std::string id(4, '?');
    for (int i = 0; i < 4; ++i) {
        const std::uint8_t c = b[at + i];
        if (c >= 32 && c < 127) id[i] = static_cast<char>(c);
    }
    return id;
}

// The chunk header at `at`: content and children must fit before `end`.
Chunk chunkAt(Bytes b, std::size_t at, std::size_t end) {
    if (end - at < 12) {
        throw VoxFailure{at, "truncated chunk header: " + std::to_string(end - at) +
                                 " bytes left in MAIN, a chunk header needs 12"};
    }
    Chunk c;
    c.id = chunkId(b, at);
    c.at = at;
    const std::int32_t n = readI32(b, at + 4), m = readI32(b, at + 8);
    if (n < 0) {
        throw VoxFailure{at + 4,
                         c.id + " chunk has a negative content size (" + std::to_string(n) + ")"};
    }
    if (m < 0) {
        throw VoxFailure{at + 8,
                         c.id + " chunk has a negative children size (" + std::to_string(m) + ")"};
    }
    const std::uint64_t left = end - (at + 12);
    const std::uint64_t claimed = static_cast<std::uint64_t>(n) + static_cast<std::uint64_t>(m);
    if (claimed > left) {
        throw VoxFailure{at + 4, c.id + " chunk claims " + std::to_string(claimed) +
                                     " bytes but only " + std::to_string(left) + " remain"};
    }
    c.content = at + 12;
    c.size = static_cast<std::size_t>(n);
    c.children = c.content + c.size;
    c.childrenSize = static_cast<std::size_t>(m);
    return c;
}

}  // namespace

std::int32_t readI32(Bytes b, std::size_t at) {
    const std::uint32_t u = static_cast<std::uint32_t>(b[at]) |
                            (static_cast<std::uint32_t>(b[at + 1]) << 8) |
                            (static_cast<std::uint32_t>(b[at + 2]) << 16) |
                            (static_cast<std::uint32_t>(b[at + 3]) << 24);
    return static_cast<std::int32_t>(u);
}

std::vector<Chunk> readChunks(Bytes b, int* version) {
    const std::size_t n = b.size();
    if (n < 8) {
        throw VoxFailure{
            0, "file is truncated: " + std::to_string(n) + " bytes, a .vox header needs 8"};
    }
    if (std::memcmp(b.data(), "VOX ", 4) != 0) {
        throw VoxFailure{0, "not a MagicaVoxel file: no \"VOX \" magic"};
    }
    const std::int32_t v = readI32(b, 4);
    if (v != 150 && v != 200) {
        throw VoxFailure{
            4, "unsupported .vox version " + std::to_string(v) + " (expected 150 or 200)"};
    }
    if (version) *version = v;
    if (n - 8 < 12) throw VoxFailure{8, "file is truncated: no MAIN chunk header"};
    const Chunk main = chunkAt(b, 8, n);
    if (main.id != "MAIN") throw VoxFailure{8, "expected the MAIN chunk, found '" + main.id + "'"};
    std::vector<Chunk> chunks;
    const std::size_t end = main.children + main.childrenSize;
    for (std::size_t at = main.children; at < end;) {
        Chunk c = chunkAt(b, at, end);
        at = c.children + c.childrenSize;
        chunks.push_back(std::move(c));
    }
    return chunks;
}

const std::string* lookup(const Dict& dict, std::string_view key) {
    for (const auto& [k, v] : dict) {
        if (k == key) return &v;
    }
    return nullptr;
}

FieldReader::FieldReader(Bytes bytes, const Chunk& chunk)
    : b_(bytes), chunk_(chunk.id), at_(chunk.content), end_(chunk.content + chunk.size) {}

void FieldReader::fail(const std::string& message) const {
    throw VoxFailure{at_, chunk_ + " chunk: " + message};
}

void FieldReader::need(std::size_t n, const char* what) const {
    if (end_ - at_ < n) {
        fail(std::string(what) + " needs " + std::to_string(n) + " bytes, " +
             std::to_string(end_ - at_) + " remain in the chunk");
    }
}

std::int32_t FieldReader::i32(const char* what) {
    need(4, what);
    const std::int32_t v = readI32(b_, at_);
    at_ += 4;
    return v;
}

std::string FieldReader::string(const char* what) {
    const std::size_t start = at_;
    const std::int32_t n = i32(what);
    if (n < 0 || static_cast<std::size_t>(n) > end_ - at_) {
        at_ = start;
        fail(std::string(what) + " claims " + std::to_string(n) + " bytes, " +
             std::to_string(end_ - start - 4) + " remain in the chunk");
    }
    std::string s(reinterpret_cast<const char*>(b_.data() + at_), static_cast<std::size_t>(n));
    at_ += static_cast<std::size_t>(n);
    return s;
}

Dict FieldReader::dict(const char* what) {
    const std::size_t start = at_;
    const std::int32_t pairs = i32(what);
    // Each pair holds two STRING lengths at least, so the count is bounded by the bytes left.
    if (pairs < 0 || static_cast<std::size_t>(pairs) > (end_ - at_) / 8) {
        at_ = start;
        fail(std::string(what) + " claims " + std::to_string(pairs) + " entries, " +
             std::to_string(end_ - start - 4) + " bytes remain in the chunk");
    }
    Dict d;
    d.reserve(static_cast<std::size_t>(pairs));
    for (std::int32_t i = 0; i < pairs; ++i) {
        std::string key = string(what);
        std::string value = string(what);
        d.emplace_back(std::move(key), std::move(value));
    }
    return d;
}

bool parseInt(std::string_view text, std::int64_t& out) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc{} && end == text.data() + text.size() && !text.empty();
}

bool parseNumber(std::string_view text, double& out) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc{} && end == text.data() + text.size() && !text.empty() &&
           std::isfinite(out);
}

}  // namespace luxel::voxel::vox
