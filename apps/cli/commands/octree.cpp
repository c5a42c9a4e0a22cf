// `luxel octree build SCENE --out F.lxo`: an octree scene's tree written as a container file;
// `luxel octree convert IN OUT`: between .lxo container files (re-validated and compacted) and,
// where luxel has OpenVDB, .vdb grids.
#include <cstdio>
#include <memory>

#include "commands/command.h"
#include "luxel/core/memory.h"
#include "luxel/core/timer.h"
#include "luxel/octree/octree_edit.h"
#include "luxel/octree/octree_file.h"

namespace luxel::cli {
namespace {

struct OctreeArgs {
    std::string scene, out, input, output;
};

int writeTree(const octree::Octree& tree, const std::string& out, double buildSeconds) {
    if (!hasExtension(out, ".lxo")) {
        return reportError(Error("--out '" + out + "' must end in .lxo"));
    }
    if (Status s = octree::writeOctreeFile(out, tree); !s) return reportError(s.error());
    const octree::OctreeStats stats = octree::measure(tree);
    std::printf(
        "wrote %s: depth %d, %llu octants, %s, %.4f bits per solid voxel (built in %.3f s)\n",
        out.c_str(), stats.depth, static_cast<unsigned long long>(stats.octants),
        formatBytes(stats.geometryBytes + stats.attributeBytes).c_str(), stats.bitsPerSolidVoxel,
        buildSeconds);
    return 0;
}

int runBuild(const OctreeArgs& args) {
    auto file = loadScene(args.scene, "");
    if (!file) return reportError(file.error());
    if (file->kind() != scene::SceneKind::Octree) {
        return reportError(Error(args.scene + ": not an octree scene (\"type\": \"octree\")"));
    }
    return writeTree(file->octree().tree, args.out, file->octree().buildSeconds);
}

int runConvert(const OctreeArgs& args) {
    if (!hasExtension(args.input, ".lxo")) {
        return reportError(Error(args.input + ": convert reads .lxo files"));
    }
    Stopwatch clock;
    auto tree = octree::readOctreeFile(args.input);
    if (!tree) return reportError(tree.error());
    return writeTree(octree::compacted(*tree), args.output, clock.seconds());
}

}  // namespace

CLI::App* addOctreeTilesCommand(CLI::App& octree, Runner& run);  // octree_tiles.cpp

Runner addOctreeCommand(CLI::App& app) {
    auto args = std::make_shared<OctreeArgs>();
    app.require_subcommand(1);
    CLI::App* build = app.add_subcommand("build", "write an octree scene's tree as a .lxo file");
    build->add_option("scene", args->scene, "octree scene (.json)")->required();
    build->add_option("--out", args->out, "container file (.lxo)")->required();
    CLI::App* convert = app.add_subcommand("convert", "convert between octree files");
    convert->add_option("input", args->input, "input (.lxo)")->required();
    convert->add_option("output", args->output, "output (.lxo)")->required();
    Runner runTiles;
    CLI::App* tiles = addOctreeTilesCommand(app, runTiles);
    return [args, build, convert, tiles, runTiles] {
        if (tiles->parsed()) return runTiles();
        if (build->parsed()) return runBuild(*args);
        if (convert->parsed()) return runConvert(*args);
        return reportError(Error("octree: choose build or convert"));
    };
}

}  // namespace luxel::cli
