#include "luxel/core/image_size.h"

#include <algorithm>
#include <charconv>

namespace luxel {
namespace {

// A whole decimal number filling `text` exactly (no sign, spaces or trailing characters).
bool parseSide(std::string_view text, long long& out) {
    if (text.empty() || text.size() > 12) return false;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc{} && end == text.data() + text.size() && text.front() != '-' &&
           text.front() != '+';
}

std::string quoted(std::string_view option, std::string_view text) {
    return std::string(option) + " '" + std::string(text) + "'";
}

Result<ImageSize> checked(long long w, long long h, std::string_view option,
                          std::string_view text) {
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide) {
        return Error(quoted(option, text) + ": each side must be in 1.." +
                     std::to_string(kMaxImageSide));
    }
    return ImageSize{static_cast<int>(w), static_cast<int>(h)};
}

}  // namespace

Result<ImageSize> parseImageSize(std::string_view text, std::string_view option) {
    const std::size_t x = text.find_first_of("xX");
    long long w = 0, h = 0;
    if (x == std::string_view::npos || !parseSide(text.substr(0, x), w) ||
        !parseSide(text.substr(x + 1), h)) {
        return Error(quoted(option, text) + " is not WIDTHxHEIGHT (e.g. 640x480)");
    }
    return checked(w, h, option, text);
}

Result<std::vector<ImageSize>> parseImageSizeList(std::string_view text, std::string_view option) {
    std::vector<ImageSize> sizes;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string_view item = text.substr(start, comma - start);
        long long side = 0;
        if (item.find_first_of("xX") != std::string_view::npos) {
            auto size = parseImageSize(item, option);
            if (!size) return size.error();
            sizes.push_back(*size);
        } else if (parseSide(item, side)) {
            auto size = checked(side, side, option, item);
            if (!size) return size.error();
            sizes.push_back(*size);
        } else {
            return Error(quoted(option, text) +
                         " is not a comma-separated list of sizes (N or WxH)");
        }
        start = comma + 1;
    }
    return sizes;
}

}  // namespace luxel
