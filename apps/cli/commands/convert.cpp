// `luxel convert WORLD OUT.vox`: writes the world of a voxel scene (or of a .vox file) as a
// MagicaVoxel file: palette, materials (MATL) and, for worlds over 256 a side, several models
// placed by a scene graph (luxel/voxel/vox_import.h).
#include <cstdio>
#include <memory>

#include "commands/command.h"
#include "luxel/voxel/vox_import.h"

namespace luxel::cli {
namespace {

struct ConvertArgs {
    std::string world, out;
    int frame = -1;
    bool quiet = false;
};

int runConvert(const ConvertArgs& args) {
    if (!hasExtension(args.out, ".vox")) {
        return reportError(Error("'" + args.out + "': convert writes MagicaVoxel files; the " +
                                 "output must end in .vox"));
    }
    auto file = loadScene(args.world, "", args.frame);
    if (!file) return reportError(file.error());
    if (file->kind() != scene::SceneKind::Voxel) {
        return reportError(Error(args.world + ": " + sceneKindPhrase(file->kind()) +
                                 "; convert takes a voxel scene or a .vox file"));
    }
    const voxel::VoxelScene& scene = file->voxel();
    auto written = voxel::writeVox(scene.world, args.out, &scene.shading.materials);
    if (!written) return reportError(written.error());
    for (const std::string& w : *written) {
        std::fprintf(stderr, "luxel: warning: %s: %s\n", args.out.c_str(), w.c_str());
    }
    if (!args.quiet) {
        const Int3 s = scene.world.size();
        std::printf("wrote %s: %dx%dx%d voxels, %llu solid\n", args.out.c_str(), s.x, s.y, s.z,
                    static_cast<unsigned long long>(scene.world.solidCount()));
    }
    return 0;
}

}  // namespace

Runner addConvertCommand(CLI::App& app) {
    auto args = std::make_shared<ConvertArgs>();
    app.add_option("world", args->world, "voxel scene (.json with \"type\": \"voxel\") or .vox")
        ->required();
    app.add_option("out", args->out, "output MagicaVoxel file (.vox)")->required();
    addVoxFrameOption(app, args->frame);
    app.add_flag("--quiet", args->quiet, "print nothing but warnings and errors");
    return [args] { return runConvert(*args); };
}

}  // namespace luxel::cli
