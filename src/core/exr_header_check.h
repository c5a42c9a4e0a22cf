// A pass over an EXR file's header attributes before OpenEXR reads them. OpenEXR allocates an
// attribute's value at the size the file declares (up to 2 GiB) before it finds the file too short,
// so a 24-byte file could make the reader reserve gigabytes; this check refuses any attribute whose
// size is negative or larger than what is left of the file, naming the attribute, and data
// windows and tiles beyond the image limits (image_io.h), which size OpenEXR's tables and buffers.
#pragma once

#include <ImfIO.h>

#include <cstdint>
#include <string>

#include "luxel/core/error.h"

namespace luxel::detail {

// Scans every header of the file (one, or all parts of a multi-part file) from the start of
// `stream` of `totalBytes`, and leaves the stream at the start again. Errors are the bare problem
// ("attribute 'comments' declares 1994962432 bytes, but only 12 are left") for callers to prefix.
Status checkExrAttributeSizes(Imf::IStream& stream, std::uint64_t totalBytes);

}  // namespace luxel::detail
