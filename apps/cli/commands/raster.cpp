// `luxel raster`: the rasterised medium as images, for debugging and for other tools.
#include <cstdio>
#include <memory>
#include <vector>

#include "commands/command.h"
#include "luxel/core/image_io.h"

namespace luxel::cli {
namespace {

struct RasterArgs {
    std::string scene, size, emission, absorption;
    int supersample = 16;
};

int runRaster(const RasterArgs& args) {
    if (args.emission.empty() && args.absorption.empty()) {
        return reportError(Error("give --emission and/or --absorption"));
    }
    auto medium = loadMedium(args.scene, args.size, args.supersample);
    if (!medium) return reportError(medium.error());
    // Both files change together or not at all.
    std::vector<ImageFile> files;
    if (!args.emission.empty()) files.push_back({args.emission, &medium->emission});
    if (!args.absorption.empty()) files.push_back({args.absorption, &medium->absorption});
    if (Status s = writeImages(files); !s) return reportError(s.error());
    std::printf("%s: %dx%d medium written\n", args.scene.c_str(), medium->width(),
                medium->height());
    return 0;
}

}  // namespace

Runner addRasterCommand(CLI::App& app) {
    auto args = std::make_shared<RasterArgs>();
    app.add_option("scene", args->scene, "scene file (.json)")->required();
    app.add_option("--size", args->size, "raster size WIDTHxHEIGHT (default: the scene canvas)");
    app.add_option("--emission", args->emission, "emission radiance image (.exr recommended)");
    app.add_option("--absorption", args->absorption, "absorption coefficient image (.exr)");
    app.add_option("--supersample", args->supersample, "edge samples per pixel side")
        ->check(wholeIn(1, 64))
        ->capture_default_str();
    return [args] { return runRaster(*args); };
}

}  // namespace luxel::cli
