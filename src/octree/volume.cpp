#include "luxel/octree/volume.h"

#include <string>

#include "luxel/core/memory.h"

namespace luxel::octree {

std::uint64_t Volume::bytesFor(Int3 size, bool withColours) {
    const std::uint64_t voxels = static_cast<std::uint64_t>(size.x) * size.y * size.z;
    return voxels * (1 + (withColours ? sizeof(Colour) : 0));
}

Result<Volume> Volume::create(Int3 size, bool withColours) {
    for (int side : {size.x, size.y, size.z}) {
        if (side < 1 || side > kMaxVolumeSide) {
            return Error("volume size " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                         "x" + std::to_string(size.z) + ": each side must be in 1.." +
                         std::to_string(kMaxVolumeSide));
        }
    }
    if (Status s = checkMemory(bytesFor(size, withColours), "a dense volume"); !s) {
        return s.error();
    }
    Volume v;
    v.size_ = size;
    v.opacity_.assign(static_cast<std::size_t>(size.x) * size.y * size.z, 0);
    if (withColours) v.colours_.assign(v.opacity_.size(), Colour{});
    return v;
}

std::uint64_t Volume::nonZeroCount() const {
    std::uint64_t n = 0;
    for (std::uint8_t o : opacity_) n += o != 0 ? 1 : 0;
    return n;
}

}  // namespace luxel::octree
