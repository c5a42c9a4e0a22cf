// Image and canvas sizes as users type them ("640x480"), parsed in one place with one limit, for
// every command-line option of the CLI, the viewer and the benches.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "luxel/core/error.h"

namespace luxel {

// The largest accepted side of any image, canvas or window (memory is checked separately, before
// anything that large is allocated).
inline constexpr int kMaxImageSide = 65536;

struct ImageSize {
    int width = 0;
    int height = 0;
    bool operator==(const ImageSize&) const = default;
};

// "WxH" (or "WXH"), each side in 1..kMaxImageSide. Errors name `option` and quote the text:
// "--size '0x5': each side must be in 1..65536".
Result<ImageSize> parseImageSize(std::string_view text, std::string_view option);

// A comma-separated list of sizes; an entry "N" means NxN. Empty lists and entries are errors.
Result<std::vector<ImageSize>> parseImageSizeList(std::string_view text, std::string_view option);

}  // namespace luxel
