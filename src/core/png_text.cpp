// Image metadata as PNG text chunks.
#include "core/png_text.h"

#include <algorithm>
#include <string>

namespace luxel::detail {

std::vector<png_text> pngTextChunks(const ImageMetadata& metadata) {
    std::vector<png_text> chunks;
    chunks.reserve(metadata.size());
    for (const MetadataEntry& entry : metadata) {
        png_text chunk{};
        // tEXt is Latin-1, so any byte above 127 (UTF-8 in luxel's strings) needs iTXt.
        const bool ascii = std::all_of(entry.value.begin(), entry.value.end(),
                                       [](char c) { return static_cast<unsigned char>(c) < 128; });
        chunk.compression = ascii ? PNG_TEXT_COMPRESSION_NONE : PNG_ITXT_COMPRESSION_NONE;
        // libpng copies the strings and never writes through these pointers.
        chunk.key = const_cast<char*>(entry.key.c_str());
        chunk.text = const_cast<char*>(entry.value.c_str());
        chunk.text_length = ascii ? entry.value.size() : 0;
        chunk.itxt_length = ascii ? 0 : entry.value.size();
        chunks.push_back(chunk);
    }
    return chunks;
}

ImageMetadata pngTextMetadata(png_const_structrp png, png_inforp info) {
    png_textp text = nullptr;
    int count = 0;
    png_get_text(png, info, &text, &count);
    ImageMetadata metadata;
    for (int i = 0; i < count; ++i) {
        const png_text& chunk = text[i];
        const std::size_t length =
            chunk.compression >= PNG_ITXT_COMPRESSION_NONE ? chunk.itxt_length : chunk.text_length;
        metadata.push_back({chunk.key != nullptr ? chunk.key : "",
                            chunk.text != nullptr ? std::string(chunk.text, length) : ""});
    }
    return metadata;
}

}  // namespace luxel::detail
