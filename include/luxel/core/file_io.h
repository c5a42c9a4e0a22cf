// Whole-file reads with a size limit, and writes that never leave a half-written file: the bytes
// go to a temporary file next to the target, which is renamed over it only once complete.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "luxel/core/error.h"

namespace luxel {

// The bytes of a file of at most `maxBytes` ("cannot open scene 'p': reason",
// "scene file 'p' is too large (at most 64 MiB)"). `what` names the kind of file.
Result<std::string> readFileBytes(const std::string& path, const std::string& what,
                                  std::uintmax_t maxBytes = std::uintmax_t{64} << 20);

// Writes `bytes` to `path` through a temporary file in the same folder and a rename, so `path`
// holds either its old content or all of the new ("cannot write octree 'p': reason").
Status writeFileAtomically(const std::string& path, std::string_view bytes,
                           const std::string& what);

}  // namespace luxel
