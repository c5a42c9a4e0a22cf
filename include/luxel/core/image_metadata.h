// Text metadata carried in image files: key/value strings, stored as EXR string attributes and as
// PNG tEXt (ASCII) or iTXt (UTF-8) chunks, so an image says how it was made.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "luxel/core/error.h"

namespace luxel {

struct MetadataEntry {
    std::string key;
    std::string value;
    bool operator==(const MetadataEntry&) const = default;
};

// In the order written; readers return the entries in the order the file holds them.
using ImageMetadata = std::vector<MetadataEntry>;

// The most bytes a key and a value may have: PNG keywords hold 1 to 79 bytes; values are kept
// well below the EXR reader's limit on attribute sizes.
constexpr std::size_t kMaxMetadataKeyBytes = 79;
constexpr std::size_t kMaxMetadataValueBytes = 65536;

// Keys are 1 to 79 printable ASCII characters without spaces ('luxel.solver'); values have no NUL
// bytes and at most kMaxMetadataValueBytes. Keys are unique. The writers refuse anything else with
// this message ("metadata key 'a b': ...").
Status checkMetadata(const ImageMetadata& metadata);

// The value of `key`, or nullptr.
const std::string* findMetadata(const ImageMetadata& metadata, std::string_view key);

// Sets `key` to `value`, replacing an entry with that key or appending one.
void setMetadata(ImageMetadata& metadata, std::string key, std::string value);

// 64-bit FNV-1a of `bytes` (offset basis 0xcbf29ce484222325, prime 0x100000001b3): a fingerprint
// of a scene file, not a cryptographic hash.
std::uint64_t fnv1a64(std::string_view bytes);
// The same as 16 lower-case hex digits.
std::string fnv1a64Hex(std::string_view bytes);

}  // namespace luxel
