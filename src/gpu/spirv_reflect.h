// What a compiled compute shader declares, read from its SPIR-V words: the workgroup size and the
// member offsets of its push-constant block and storage-buffer elements. The runtime takes the
// workgroup size from here (so it is declared once, in the shader), and the layout tests compare
// the offsets glslc emitted with the C++ offsetof of the shared structs.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "luxel/core/error.h"

namespace luxel::gpu {

// A struct as the shader lays it out: byte offset of each member, in declaration order.
struct SpirvStruct {
    std::vector<std::uint32_t> offsets;
    std::uint32_t arrayStride = 0;  // for a buffer element: the stride of its runtime array
};

struct SpirvReflection {
    std::array<std::uint32_t, 3> workgroupSize{0, 0, 0};
    // The struct inside the push-constant block (`uniform Push { Params params; }`), or the
    // block itself when its members are scalars; empty when the shader has no push constants.
    SpirvStruct pushConstants;
    bool hasPushConstants = false;

    // The struct in the storage buffer at (set 0, binding): the element of its runtime array,
    // `buffer B { Element e[]; }` (arrayStride set), or its one member, `buffer B { Params p; }`.
    // An error when the binding does not exist or holds an array of scalars or vectors.
    Result<SpirvStruct> bufferElement(std::uint32_t binding) const;

    // Every storage-buffer binding of set 0, ascending.
    std::vector<std::uint32_t> bufferBindings() const;

    struct Tables;
    std::shared_ptr<const Tables> tables;
};

// Parses SPIR-V words (as embedded by cmake/SpirvToCpp.cmake); an error names what is malformed.
Result<SpirvReflection> reflectSpirv(std::span<const std::uint32_t> words);

}  // namespace luxel::gpu
