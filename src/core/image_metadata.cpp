// Image metadata checks and lookup, and the FNV-1a fingerprint of scene files.
#include "luxel/core/image_metadata.h"

#include <cstdio>
#include <set>

namespace luxel {

Status checkMetadata(const ImageMetadata& metadata) {
    std::set<std::string_view> keys;
    for (const MetadataEntry& entry : metadata) {
        const std::string quoted = "metadata key '" + entry.key.substr(0, 100) + "'";
        if (entry.key.empty() || entry.key.size() > kMaxMetadataKeyBytes) {
            return Error(quoted + ": must have 1 to " + std::to_string(kMaxMetadataKeyBytes) +
                         " characters");
        }
        for (char c : entry.key) {
            // PNG keywords are Latin-1 without leading, trailing or double spaces; printable ASCII
            // without any space is the part every reader shows the same way.
            if (c <= ' ' || c > '~') {
                return Error(quoted + ": only printable ASCII characters without spaces");
            }
        }
        if (entry.value.size() > kMaxMetadataValueBytes) {
            return Error(quoted + ": the value has more than " +
                         std::to_string(kMaxMetadataValueBytes) + " bytes");
        }
        if (entry.value.find('\0') != std::string::npos) {
            return Error(quoted + ": the value contains a NUL byte");
        }
        if (!keys.insert(entry.key).second) return Error(quoted + ": given twice");
    }
    return Ok{};
}

const std::string* findMetadata(const ImageMetadata& metadata, std::string_view key) {
    for (const MetadataEntry& entry : metadata) {
        if (entry.key == key) return &entry.value;
    }
    return nullptr;
}

void setMetadata(ImageMetadata& metadata, std::string key, std::string value) {
    for (MetadataEntry& entry : metadata) {
        if (entry.key == key) {
            entry.value = std::move(value);
            return;
        }
    }
    metadata.push_back({std::move(key), std::move(value)});
}

std::uint64_t fnv1a64(std::string_view bytes) {
    std::uint64_t hash = 0xcbf29ce484222325ull;
    for (unsigned char byte : bytes) {
        hash ^= byte;
        hash *= 0x100000001b3ull;
    }
    return hash;
}

std::string fnv1a64Hex(std::string_view bytes) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(fnv1a64(bytes)));
    return text;
}

}  // namespace luxel
