// The SPIR-V compiled from src/gpu/shaders at build time (generated shader_registry_data.cpp).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace luxel::gpu::detail {

struct EmbeddedShader {
    std::string_view name;
    std::span<const std::uint32_t> words;
};

extern const EmbeddedShader kEmbeddedShaders[];
extern const int kEmbeddedShaderCount;
// False in a build without the GPU backend (LUXEL_GPU=OFF), which compiles and embeds no shader.
extern const bool kShadersEmbedded;

// Words of the shader called `name` (file name without .comp.glsl); empty when there is none.
inline std::span<const std::uint32_t> embeddedShader(std::string_view name) {
    for (int i = 0; i < kEmbeddedShaderCount; ++i) {
        if (kEmbeddedShaders[i].name == name) return kEmbeddedShaders[i].words;
    }
    return {};
}

}  // namespace luxel::gpu::detail
