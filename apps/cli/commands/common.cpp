// Helpers shared by the CLI subcommands.
#include <cctype>
#include <cstdio>
#include <string_view>

#include "commands/command.h"
#include "luxel/core/image_size.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/scene2d_json.h"
#include "luxel/gpu/backend_policy.h"
#include "luxel/gpu/context.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {

int reportError(const Error& error) {
    std::fprintf(stderr, "luxel: error: %s\n", error.message().c_str());
    return kExitBadInput;
}

bool hasExtension(const std::string& path, const std::string& ext) {
    if (path.size() < ext.size()) return false;
    std::string tail = path.substr(path.size() - ext.size());
    for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return tail == ext;
}

Result<std::pair<int, int>> parseSize(const std::string& text) {
    if (text.empty()) return std::pair{0, 0};
    auto size = parseImageSize(text, "--size");
    if (!size) return size.error();
    return std::pair{size->width, size->height};
}

Result<scene::SceneFile> loadScene(const std::string& scenePath, const std::string& size,
                                   int voxFrame) {
    auto dims = parseSize(size);
    if (!dims) return dims.error();
    auto file = scene::loadSceneFile(scenePath, {{dims->first, dims->second}, voxFrame});
    if (file && file->kind() == scene::SceneKind::Voxel) printWarnings(file->voxel().warnings);
    return file;
}

void printWarnings(const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings) std::fprintf(stderr, "luxel: warning: %s\n", w.c_str());
}

const char* sceneKindPhrase(scene::SceneKind kind) {
    switch (kind) {
        case scene::SceneKind::Voxel:
            return "a voxel scene";
        case scene::SceneKind::Octree:
            return "an octree scene";
        case scene::SceneKind::TwoD:
            break;
    }
    return "a 2D scene";
}

Result<SizedScene> loadSizedScene(const std::string& scenePath, const std::string& size) {
    auto file = loadScene(scenePath, "");
    if (!file) return file.error();
    if (file->kind() != scene::SceneKind::TwoD) {
        return Error(scenePath + ": " + sceneKindPhrase(file->kind()) +
                     "; this command works on 2D scenes");
    }
    return sizeScene(std::move(file->twoD()), size);
}

Result<SizedScene> sizeScene(gi2d::Scene2D scene, const std::string& size) {
    auto dims = parseSize(size);
    if (!dims) return dims.error();
    SizedScene sized{std::move(scene), dims->first, dims->second};
    if (sized.width == 0) {
        sized.width = sized.scene.width;
        sized.height = sized.scene.height;
    }
    return sized;
}

Result<gi2d::Medium2D> rasterizeSized(const SizedScene& sized, const std::string& scenePath,
                                      int supersample) {
    const gi2d::RasterOptions options{sized.width, sized.height, supersample};
    auto medium = gi2d::rasterize(sized.scene, options);
    if (!medium) return Error(scenePath + ": " + medium.error().message());
    return medium;
}

Result<gi2d::Medium2D> loadMedium(const std::string& scenePath, const std::string& size,
                                  int supersample) {
    auto sized = loadSizedScene(scenePath, size);
    if (!sized) return sized.error();
    return rasterizeSized(*sized, scenePath, supersample);
}

Result<std::unique_ptr<gpu::Context>> chooseGpuBackend(gpu::Backend backend,
                                                       const std::string& device, bool quiet) {
#ifdef NDEBUG
    constexpr bool kValidation = false;
#else
    constexpr bool kValidation = true;  // debug builds run with the validation layers
#endif
    auto choice = gpu::openBackend(backend, {device, kValidation});
    if (!choice) return choice.error();
    if (!choice->note.empty() && !quiet) {
        std::fprintf(stderr, "luxel: note: %s\n", choice->note.c_str());
    }
    return std::move(choice->context);
}

Result<gpu::Backend> parseBenchBackend(const std::string& text) {
    auto backend = gpu::parseBackend(text);
    if (!backend || *backend == gpu::Backend::Auto) {
        return Error("--backend '" + text + "' is not cpu or gpu");
    }
    return *backend;
}

Result<std::unique_ptr<gpu::Context>> openBenchGpu(const std::string& device) {
    auto context = gpu::Context::create({device, false});
    if (!context) return Error("--backend gpu: " + context.error().message());
    std::printf("device: %s (%s)\n", (*context)->device().name.c_str(),
                (*context)->device().type.c_str());
    return std::move(*context);
}

}  // namespace luxel::cli
