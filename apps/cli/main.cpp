// luxel: render 2D light-transport scenes, inspect them and compare images.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <map>
#include <string>

#include "commands/command.h"
#include "common/last_resort.h"

int main(int argc, char** argv) {
    CLI::App app{"luxel: real-time light transport in 2D and voxel worlds"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("luxel ") + LUXEL_VERSION);
    std::map<CLI::App*, luxel::cli::Runner> runners;
    auto add = [&](const char* name, const char* help, auto addCommand) {
        CLI::App* sub = app.add_subcommand(name, help);
        runners[sub] = addCommand(*sub);
    };
    add("render", "render a scene to a fluence image", luxel::cli::addRenderCommand);
    add("info", "describe a scene and the memory it needs", luxel::cli::addInfoCommand);
    add("compare", "compare two images (RMSE, relative L1, max error)",
        luxel::cli::addCompareCommand);
    add("compare-solvers", "run every 2D solver on a scene: time, error vs reference, memory",
        luxel::cli::addCompareSolversCommand);
    add("bench", "HRC frame times over canvas sizes, CPU or GPU, per pass",
        luxel::cli::addBenchCommand);
    add("devices", "list the Vulkan devices the GPU backend can use",
        luxel::cli::addDevicesCommand);
    add("raster", "write the rasterised medium (emission, absorption) as images",
        luxel::cli::addRasterCommand);
    add("upscale", "native vs lower internal resolution + upscaler: PSNR, SSIM, time",
        luxel::cli::addUpscaleCommand);
    add("octree", "build or convert sparse voxel octrees (.lxo container files)",
        luxel::cli::addOctreeCommand);
    add("shadows", "sun visibility by every shadow method against ray-traced truth",
        luxel::cli::addShadowsCommand);
    add("convert", "write a voxel world (scene or .vox) as a MagicaVoxel .vox file",
        luxel::cli::addConvertCommand);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ValidationError& e) {
        // Out-of-range and unparsable option values: one line, like every other bad input.
        std::fprintf(stderr, "luxel: error: %s\n", e.what());
        return luxel::cli::kExitBadInput;
    } catch (const CLI::ConversionError& e) {
        std::fprintf(stderr, "luxel: error: %s\n", e.what());
        return luxel::cli::kExitBadInput;
    } catch (const CLI::ParseError& e) {
        // --help and --version end parsing with exit code 0 and print what was asked for.
        if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
        // Every other parse error (a missing argument, an unknown option, an extra value) is bad
        // input like any other: one line and exit code 1, not CLI11's own codes (106 and so on).
        std::fprintf(stderr, "luxel: error: %s (see 'luxel --help')\n", e.what());
        return luxel::cli::kExitBadInput;
    }
    for (auto& [sub, run] : runners) {
        if (sub->parsed()) {
            return luxel::options::runUntilOutOfMemory("luxel", "running '" + sub->get_name() + "'",
                                                       run);
        }
    }
    return 0;
}
