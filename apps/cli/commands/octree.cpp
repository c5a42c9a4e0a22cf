// `luxel octree build SCENE --out F.lxo|F.vdb`: an octree scene's tree written as a container file
// or an OpenVDB grid; `luxel octree convert IN OUT`: between .lxo container files (re-validated
// and compacted) and .vdb grids (luxel/octree/octree_vdb.h), either way.
#include <cstdio>
#include <memory>

#include "commands/command.h"
#include "luxel/core/memory.h"
#include "luxel/core/timer.h"
#include "luxel/octree/octree_edit.h"
#include "luxel/octree/octree_file.h"
#include "luxel/octree/octree_vdb.h"

namespace luxel::cli {
namespace {

struct OctreeArgs {
    std::string scene, out, input, output;
    octree::VdbImportOptions vdb;  // --grid, --max
};

int writeTree(const octree::Octree& tree, const std::string& out, double buildSeconds) {
    Status written = Ok{};
    if (hasExtension(out, ".lxo")) {
        written = octree::writeOctreeFile(out, tree);
    } else if (hasExtension(out, ".vdb")) {
        written = octree::exportVdb(tree, out);
    } else {
        return reportError(Error("--out '" + out + "' must end in .lxo or .vdb"));
    }
    if (!written) return reportError(written.error());
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
    Stopwatch clock;
    Result<octree::Octree> tree = Error("");
    if (hasExtension(args.input, ".vdb")) {
        tree = octree::importVdb(args.input, args.vdb);
    } else if (hasExtension(args.input, ".lxo")) {
        if (!args.vdb.grid.empty() || args.vdb.max > 0) {
            return reportError(Error(args.input + ": --grid and --max apply to .vdb input"));
        }
        tree = octree::readOctreeFile(args.input);
        if (tree) tree = octree::compacted(*tree);
    } else {
        return reportError(Error(args.input + ": convert reads .lxo or .vdb files"));
    }
    if (!tree) return reportError(tree.error());
    return writeTree(*tree, args.output, clock.seconds());
}

}  // namespace

CLI::App* addOctreeTilesCommand(CLI::App& octree, Runner& run);  // octree_tiles.cpp

Runner addOctreeCommand(CLI::App& app) {
    auto args = std::make_shared<OctreeArgs>();
    app.require_subcommand(1);
    CLI::App* build =
        app.add_subcommand("build", "write an octree scene's tree as a .lxo or .vdb file");
    build->add_option("scene", args->scene, "octree scene (.json)")->required();
    build->add_option("--out", args->out, "container file (.lxo) or OpenVDB grid (.vdb)")
        ->required();
    CLI::App* convert =
        app.add_subcommand("convert", "convert between octree files (.lxo) and OpenVDB (.vdb)");
    convert->add_option("input", args->input, "input (.lxo or .vdb)")->required();
    convert->add_option("output", args->output, "output (.lxo or .vdb)")->required();
    convert->add_option("--grid", args->vdb.grid,
                        ".vdb input: the float grid (default: the first)");
    convert
        ->add_option("--max", args->vdb.max,
                     ".vdb input: the fog value that maps to opacity 255 (default 1)")
        ->check(finiteIn(1e-30, 1e30));
    Runner runTiles;
    CLI::App* tiles = addOctreeTilesCommand(app, runTiles);
    return [args, build, convert, tiles, runTiles] {
        if (tiles->parsed()) return runTiles();
        if (build->parsed()) return runBuild(*args);
        if (convert->parsed()) return runConvert(*args);
        return reportError(Error("octree: choose build, convert or tiles"));
    };
}

}  // namespace luxel::cli
