// The RIFF layer of MagicaVoxel .vox files (ephtracy/voxel-model, MagicaVoxel-file-format-vox.txt
// and MagicaVoxel-file-format-vox-extension.txt): the header, MAIN's child chunks, and the typed
// fields inside a chunk (int32, STRING, DICT). Every read is checked against the bytes that are
// there; a failure is a VoxFailure naming the byte offset, turned into an Error by the reader.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace luxel::voxel::vox {

using Bytes = std::span<const std::uint8_t>;

// Thrown by the readers below; the importer turns it into "name: byte N: message".
struct VoxFailure {
    std::size_t at;
    std::string message;
};

std::int32_t readI32(Bytes bytes, std::size_t at);

// A chunk inside MAIN: its id ("????" for unprintable bytes), header offset, content span and
// the span of its children.
struct Chunk {
    std::string id;
    std::size_t at = 0;
    std::size_t content = 0, size = 0;
    std::size_t children = 0, childrenSize = 0;
};

// Checks the header ("VOX ", version 150 or 200, MAIN) and returns MAIN's children in file order
// (children of those children are not descended into: MagicaVoxel writes none).
std::vector<Chunk> readChunks(Bytes bytes, int* version = nullptr);

using Dict = std::vector<std::pair<std::string, std::string>>;

// The value of `key` in a DICT, or null.
const std::string* lookup(const Dict& dict, std::string_view key);

// Reads the fields of one chunk's content in order.
class FieldReader {
  public:
    FieldReader(Bytes bytes, const Chunk& chunk);
    std::int32_t i32(const char* what);
    std::string string(const char* what);
    Dict dict(const char* what);
    std::size_t offset() const { return at_; }
    std::size_t left() const { return end_ - at_; }
    [[noreturn]] void fail(const std::string& message) const;

  private:
    void need(std::size_t n, const char* what) const;
    Bytes b_;
    std::string chunk_;
    std::size_t at_, end_;
};

// Parses a whole number from a DICT value ("-12"); false for anything else (overflow included).
bool parseInt(std::string_view text, std::int64_t& out);
// Parses a finite number ("0.25", "1e-3"); false for anything else.
bool parseNumber(std::string_view text, double& out);

}  // namespace luxel::voxel::vox
