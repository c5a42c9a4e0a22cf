// Layout checks of shared C++/GLSL structs against the compiled shaders, for the GPU tests: read
// the member offsets (SPIR-V OpMemberDecorate ... Offset) and array strides glslc emitted into the
// embedded words and compare them with the C++ offsetof and sizeof of the same struct.
#ifndef LUXEL_TESTS_GPU_LAYOUT_CHECK_H
#define LUXEL_TESTS_GPU_LAYOUT_CHECK_H

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "gpu/embedded_shaders.h"
#include "gpu/spirv_reflect.h"

// Skips a test that reads the compiled shaders in a build without the GPU backend (LUXEL_GPU=OFF),
// which compiles none; with the backend, a missing shader still fails the test.
#define LUXEL_REQUIRE_EMBEDDED_SHADERS()         \
    if (!::luxel::gpu::detail::kShadersEmbedded) \
    GTEST_SKIP() << "luxel was built without the GPU backend (LUXEL_GPU=OFF): no shaders"

namespace luxel::gpu::layout_check {

// The C++ side of one struct: its size and the offsetof of every member, in declaration order.
struct CppLayout {
    std::size_t size = 0;
    std::vector<std::size_t> offsets;
};

#define LUXEL_MEMBER(S, m) offsetof(S, m)

// Mismatches between the shader's layout of a struct and the C++ one, one line each (empty when
// they agree). `element`: the struct is a runtime array's element, so its stride must be sizeof.
inline std::vector<std::string> compareLayouts(const SpirvStruct& shader, const CppLayout& cpp,
                                               bool element) {
    std::vector<std::string> problems;
    if (shader.offsets.size() != cpp.offsets.size()) {
        problems.push_back("the shader's struct has " + std::to_string(shader.offsets.size()) +
                           " members, C++ lists " + std::to_string(cpp.offsets.size()));
        return problems;
    }
    for (std::size_t m = 0; m < cpp.offsets.size(); ++m) {
        if (shader.offsets[m] != cpp.offsets[m]) {
            problems.push_back("member " + std::to_string(m) + " is at byte " +
                               std::to_string(shader.offsets[m]) + " in the shader, " +
                               std::to_string(cpp.offsets[m]) + " in C++");
        }
    }
    if (element && shader.arrayStride != cpp.size) {
        problems.push_back("array stride " + std::to_string(shader.arrayStride) +
                           " in the shader, sizeof " + std::to_string(cpp.size) + " in C++");
    }
    return problems;
}

inline SpirvReflection reflect(const std::string& shader) {
    const auto words = detail::embeddedShader(shader);
    EXPECT_FALSE(words.empty()) << "no embedded shader " << shader;
    auto reflection = reflectSpirv(words);
    EXPECT_TRUE(reflection.ok()) << shader << ": " << reflection.error().message();
    return reflection.ok() ? std::move(*reflection) : SpirvReflection{};
}

inline void expectPushConstants(const std::string& shader, const CppLayout& cpp) {
    const SpirvReflection r = reflect(shader);
    ASSERT_TRUE(r.hasPushConstants) << shader << " has no push-constant block";
    for (const std::string& p : compareLayouts(r.pushConstants, cpp, false)) {
        ADD_FAILURE() << shader << " push constants: " << p;
    }
}

inline void expectBuffer(const std::string& shader, std::uint32_t binding, const CppLayout& cpp,
                         bool element = true) {
    const SpirvReflection r = reflect(shader);
    auto s = r.bufferElement(binding);
    ASSERT_TRUE(s.ok()) << shader << ": " << s.error().message();
    for (const std::string& p : compareLayouts(*s, cpp, element)) {
        ADD_FAILURE() << shader << " binding " << binding << ": " << p;
    }
}

}  // namespace luxel::gpu::layout_check

#endif
