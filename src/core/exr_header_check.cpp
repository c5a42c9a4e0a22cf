// Attribute sizes of an EXR header against the file size (exr_header_check.h). Layout (OpenEXR's
// file format): magic (4), version and flags (4), then per header attributes of a null-terminated
// name, a null-terminated type name, an int32 size and the value, ended by an empty name; a
// multi-part file (flag 0x1000) has further headers, ended by an empty header.
#include "core/exr_header_check.h"

#include <array>
#include <cstdint>
#include <string>

#include "luxel/core/image_io.h"
#include "luxel/core/image_size.h"

namespace luxel::detail {
namespace {

constexpr std::uint32_t kMultiPartFlag = 0x1000;
constexpr std::size_t kMaxNameBytes = 256;  // names are at most 255 characters

// Reads a null-terminated string; false at the end of the file or for an over-long name.
bool readName(Imf::IStream& stream, std::uint64_t totalBytes, std::string& out) {
    out.clear();
    char c = 0;
    while (stream.tellg() < totalBytes) {
        stream.read(&c, 1);
        if (c == '\0') return true;
        if (out.size() == kMaxNameBytes) return false;
        out.push_back(c);
    }
    return false;
}

std::uint32_t littleEndian(const unsigned char* b) {
    return b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t{b[3]} << 24);
}

// The name with control and non-ASCII bytes shown as '?', so the message stays one plain line.
std::string printable(std::string name) {
    for (char& c : name) {
        if (c < 0x20 || c > 0x7e) c = '?';
    }
    return name;
}

// The data window and the tile size decide how much OpenEXR allocates for its offset tables and
// line or tile buffers, so they are held to the image limits before OpenEXR sees them.
Status checkValue(Imf::IStream& stream, const std::string& name, const std::string& type,
                  std::int32_t size) {
    if (name == "dataWindow" && type == "box2i" && size == 16) {
        std::array<unsigned char, 16> b{};
        stream.read(reinterpret_cast<char*>(b.data()), 16);
        const std::int64_t width = std::int64_t{static_cast<std::int32_t>(littleEndian(&b[8]))} -
                                   static_cast<std::int32_t>(littleEndian(&b[0])) + 1;
        const std::int64_t height = std::int64_t{static_cast<std::int32_t>(littleEndian(&b[12]))} -
                                    static_cast<std::int32_t>(littleEndian(&b[4])) + 1;
        if (width > kMaxImageSide || height > kMaxImageSide ||
            (width > 0 && height > 0 &&
             static_cast<std::uint64_t>(width * height) > kMaxImagePixels)) {
            return Error("image too large (" + std::to_string(width) + "x" +
                         std::to_string(height) + "; the limit is " +
                         std::to_string(kMaxImageSide) + " per side and " +
                         std::to_string(kMaxImagePixels) + " pixels)");
        }
    } else if (name == "tiles" && type == "tiledesc" && size == 9) {
        std::array<unsigned char, 8> b{};
        stream.read(reinterpret_cast<char*>(b.data()), 8);
        const std::uint32_t x = littleEndian(&b[0]), y = littleEndian(&b[4]);
        if (x > static_cast<std::uint32_t>(kMaxImageSide) ||
            y > static_cast<std::uint32_t>(kMaxImageSide) ||
            std::uint64_t{x} * y > kMaxImagePixels) {
            return Error("tiles of " + std::to_string(x) + "x" + std::to_string(y) +
                         " are larger than the image limits (" + std::to_string(kMaxImageSide) +
                         " per side and " + std::to_string(kMaxImagePixels) + " pixels)");
        }
    }
    return Ok{};
}

Status scan(Imf::IStream& stream, std::uint64_t totalBytes) {
    if (totalBytes < 8) return Ok{};  // OpenEXR reports the short file itself
    std::array<unsigned char, 8> start{};
    stream.read(reinterpret_cast<char*>(start.data()), 8);
    const std::uint32_t flags =
        start[4] | (start[5] << 8) | (start[6] << 16) | (std::uint32_t{start[7]} << 24);
    const bool multiPart = (flags & kMultiPartFlag) != 0;
    std::string name, type;
    for (int header = 0;; ++header) {
        for (int attribute = 0;; ++attribute) {
            if (!readName(stream, totalBytes, name)) return Ok{};  // OpenEXR's own error
            if (name.empty()) {
                // An empty header ends a multi-part file; an empty name ends a header.
                if (!multiPart || attribute == 0) return Ok{};
                break;
            }
            if (!readName(stream, totalBytes, type)) return Ok{};
            if (totalBytes - stream.tellg() < 4) return Ok{};
            std::array<unsigned char, 4> b{};
            stream.read(reinterpret_cast<char*>(b.data()), 4);
            const std::int32_t size = static_cast<std::int32_t>(b[0] | (b[1] << 8) | (b[2] << 16) |
                                                                (std::uint32_t{b[3]} << 24));
            const std::uint64_t valueAt = stream.tellg();
            const std::uint64_t left = totalBytes - valueAt;
            if (size < 0 || static_cast<std::uint64_t>(size) > left) {
                return Error("attribute '" + printable(name) + "' declares " +
                             std::to_string(size) + " bytes, but only " + std::to_string(left) +
                             " are left");
            }
            if (Status s = checkValue(stream, name, type, size); !s) return s;
            stream.seekg(valueAt + static_cast<std::uint64_t>(size));
        }
        if (!multiPart) return Ok{};
    }
}

}  // namespace

Status checkExrAttributeSizes(Imf::IStream& stream, std::uint64_t totalBytes) {
    Status status = scan(stream, totalBytes);
    stream.clear();
    stream.seekg(0);
    return status;
}

}  // namespace luxel::detail
