// The six axis-aligned face normals of a voxel by index, as the cascades' face table, the GPU's
// near lists and the sun rays' maps number them: 2 * axis + (component < 0), so 0 +x, 1 -x,
// 2 +y, 3 -y, 4 +z, 5 -z. Inline: the picture asks at every face lookup.
#pragma once

#include "luxel/core/vec.h"

namespace luxel::voxel {

inline int normalIndex(Int3 n) {
    if (n.x != 0) return n.x > 0 ? 0 : 1;
    if (n.y != 0) return n.y > 0 ? 2 : 3;
    return n.z > 0 ? 4 : 5;
}

inline Int3 normalFromIndex(int index) {
    Int3 n{};
    n[index / 2] = (index % 2) ? -1 : 1;
    return n;
}

}  // namespace luxel::voxel
