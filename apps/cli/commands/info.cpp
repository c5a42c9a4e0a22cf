// `luxel info`: what a scene holds and the memory rendering it needs (voxel scenes:
// info_voxel.cpp), or an image's size and metadata.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "commands/command.h"
#include "commands/render_memory.h"
#include "commands/scene_warnings.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/scene2d_json.h"
#include "luxel/gi2d/solver_choice.h"
#include "luxel/voxel/voxel_scene.h"

namespace luxel::cli {
namespace {

struct InfoArgs {
    std::string scene, size, solverName = "reference", mergeName = "bilinear-fix";
    int rays = gi2d::ReferenceOptions{}.rays;
    int frame = -1;  // --frame: a MagicaVoxel world's animation frame
};

void printRgb(const char* label, Rgb v) {
    std::printf("  %-18s (%g, %g, %g)\n", label, v.r, v.g, v.b);
}

// `luxel info IMAGE.exr|png`: its size and the metadata luxel (or another program) wrote into it.
int runImageInfo(const std::string& path) {
    ImageMetadata metadata;
    auto image = readImage(path, &metadata);
    if (!image) return reportError(image.error());
    std::printf("%s\n", path.c_str());
    std::printf("  image              %dx%d, %d channels (%s)\n", image->width(), image->height(),
                image->channels(), hasExtension(path, ".exr") ? "EXR, linear float" : "PNG, 8-bit");
    if (metadata.empty()) {
        std::printf("  metadata           none\n");
        return 0;
    }
    std::printf("  metadata           %zu entries\n", metadata.size());
    std::size_t width = 0;
    for (const MetadataEntry& entry : metadata) width = std::max(width, entry.key.size());
    for (const MetadataEntry& entry : metadata) {
        std::printf("    %-*s  %s\n", static_cast<int>(width), entry.key.c_str(),
                    entry.value.c_str());
    }
    return 0;
}

int runInfo(const InfoArgs& args) {
    if (hasExtension(args.scene, ".exr") || hasExtension(args.scene, ".png")) {
        return runImageInfo(args.scene);
    }
    auto solver = gi2d::parseSolver2D(args.solverName);
    if (!solver) return reportError(solver.error());
    auto merge = gi2d::parseRcMerge(args.mergeName);
    if (!merge) return reportError(merge.error());
    auto file = loadScene(args.scene, args.size, args.frame);
    if (!file) return reportError(file.error());
    if (file->kind() == scene::SceneKind::Voxel) return infoVoxelScene(file->voxel());
    if (file->kind() == scene::SceneKind::Octree) return infoOctreeScene(file->octree());
    auto dims = parseSize(args.size);
    if (!dims) return reportError(dims.error());
    gi2d::Scene2D* scene = &file->twoD();
    const int w = dims->first > 0 ? dims->first : scene->width;
    const int h = dims->first > 0 ? dims->second : scene->height;

    std::printf("%s\n", args.scene.c_str());
    std::printf("  canvas             %dx%d\n", scene->width, scene->height);
    if (w != scene->width || h != scene->height) std::printf("  render size        %dx%d\n", w, h);
    printRgb("background E", scene->background.emission);
    printRgb("background sigma", scene->background.absorption);
    printRgb("boundary radiance", scene->boundaryRadiance);
    std::printf("  shapes             %zu\n", scene->shapes.size());
    for (std::size_t i = 0; i < scene->shapes.size(); ++i) {
        const gi2d::Shape& s = scene->shapes[i];
        const Rgb e = s.material.scaledEmission(), a = s.material.absorption;
        std::printf("    %2zu %-8s %-16s E (%g, %g, %g)  sigma (%g, %g, %g)\n", i,
                    gi2d::geometryTypeName(s.geometry), s.name.c_str(), e.r, e.g, e.b, a.r, a.g,
                    a.b);
    }
    for (const std::string& warning : silentEmitterWarnings(*scene)) {
        printWarning(args.scene + ": " + warning);
    }
    // Bounce light: scattering fog (non-opaque albedo) and reflective surfaces (opaque albedo).
    if (gi2d::sceneBounces(*scene)) {
        int reflective = 0, scattering = 0;
        for (const gi2d::Shape& s : scene->shapes) {
            if (s.material.albedo == Rgb()) continue;
            ++(s.material.isOpaque() ? reflective : scattering);
        }
        std::printf(
            "  bounce light       yes: background albedo (%g, %g, %g), %d reflective and %d "
            "scattering shapes\n",
            scene->background.albedo.r, scene->background.albedo.g, scene->background.albedo.b,
            reflective, scattering);
    } else {
        std::printf("  bounce light       no (no albedo anywhere)\n");
    }
    gi2d::RcOptions rc;
    rc.merge = *merge;
    const Memory2D memory = estimate2D(w, h, *solver, rc, gi2d::sceneBounces(*scene));
    switch (*solver) {
        case gi2d::Solver2D::Reference:
            std::printf("  reference solver: %.3g rays at %d rays/pixel\n",
                        static_cast<double>(gi2d::referenceRayCount(w, h, args.rays)), args.rays);
            break;
        case gi2d::Solver2D::Hrc: {
            const gi2d::HrcMemory m = gi2d::estimateHrcMemory(w, h);
            std::printf(
                "  hrc: %d cascades; ray intervals %s, cones %s, medium columns %s, near-light "
                "mask %s, output %s\n",
                gi2d::hrcCascadeCount(w, h), formatBytes(m.rayIntervals).c_str(),
                formatBytes(m.cones).c_str(), formatBytes(m.mediumColumns).c_str(),
                formatBytes(m.nearLights).c_str(), formatBytes(m.output).c_str());
            break;
        }
        case gi2d::Solver2D::Rc:
            std::printf("  rc (%s merge): %zu cascades, %s\n", gi2d::mergeName(*merge),
                        gi2d::rcCascades(w, h, rc).size(), formatBytes(memory.solver).c_str());
            break;
    }
    std::printf(
        "  memory: medium %s, bounce light %s, %s in all with the %s solver and the images "
        "written (available %s)\n",
        formatBytes(memory.medium).c_str(), formatBytes(memory.bounce).c_str(),
        formatBytes(memory.total()).c_str(), gi2d::solverName(*solver),
        formatBytes(availableMemoryBytes()).c_str());
    // The same estimate and refusal as `luxel render`.
    if (Status s = checkRenderMemory(w, h, memory.total(),
                                     std::string(" with ") + gi2d::solverName(*solver));
        !s) {
        return reportError(s.error());
    }
    return 0;
}

}  // namespace

Runner addInfoCommand(CLI::App& app) {
    auto args = std::make_shared<InfoArgs>();
    app.add_option("scene", args->scene,
                   "scene file (.json), or an image (.exr, .png) to show its "
                   "metadata")
        ->required();
    app.add_option("--size", args->size, "render size WIDTHxHEIGHT (default: the scene canvas)");
    addVoxFrameOption(app, args->frame);
    app.add_option("--solver", args->solverName, "solver to estimate for: reference, hrc, rc")
        ->capture_default_str();
    app.add_option("--merge", args->mergeName, "RC: vanilla or bilinear-fix")
        ->capture_default_str();
    app.add_option("--rays", args->rays, "directions per pixel")
        ->check(wholeIn(1, gi2d::kMaxReferenceRays))
        ->capture_default_str();
    return [args] { return runInfo(*args); };
}

}  // namespace luxel::cli
