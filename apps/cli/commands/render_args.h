// The options of `luxel render` as given on the command line (render_options.cpp registers
// them) and the render they ask for (render.cpp).
#pragma once

#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/render_outputs.h"
#include "luxel/gi2d/bounce.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/solver_choice.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/sky_visibility.h"

namespace luxel::cli {

struct RenderArgs {
    std::string scene, solverName = "reference", size, out, png, tonemap = "aces";
    gi2d::Solver2D solver = gi2d::Solver2D::Reference;  // parsed from solverName
    bool pathSolver = false;                            // --solver path (voxel scenes)
    bool aoSolver = false;                              // --solver ao (voxel scenes)
    bool rayCastSolver = false;  // --solver raycast (voxel scenes: the ray caster, the default)
    std::vector<std::string> options2DGiven;  // 2D-only options on the command line
    int rays = gi2d::ReferenceOptions{}.rays;
    int threads = 0;
    int supersample = 16;
    std::uint64_t seed = 1;
    std::string exposureText;  // --exposure: stops or "auto"
    ExposureFlag exposure;     // parsed from exposureText
    bool quiet = false;
    bool stats = false;  // print a machine-readable timing line (for compare-solvers)
    int frame = -1;      // --frame: a MagicaVoxel world's animation frame
    double sunYaw = 0;   // --sun-yaw: voxel scenes, degrees the sun turns about the vertical
    bool sunYawGiven = false;
    std::string backendName = "auto", device;
    gpu::Backend backend = gpu::Backend::Auto;  // parsed from backendName
    // HRC
    int tracedLevels = gi2d::HrcOptions{}.tracedLevels;
    bool noBlur = false;
    bool noNearField = false;
    bool noDirectLight = false;
    std::string frustum;  // debug: one of +x, +y, -x, -y
    int cascade = 0;      // debug: the cascade --view cascade|probes shows (hrc, rc)
    // RC
    std::string mergeName = "bilinear-fix", march = "auto", view = "gi";
    gi2d::RcMerge merge = gi2d::RcMerge::BilinearFix;  // parsed from mergeName
    int probeSpacing = gi2d::RcOptions{}.probeSpacing;
    int baseRays = gi2d::RcOptions{}.baseRays;
    double baseInterval = gi2d::RcOptions{}.baseInterval;
    int maxCascades = 0;
    int jitters = 1;
    // Bounce light: -1 = the solver's default when the scene bounces (gi2d/bounce.h)
    int bounces = -1;
    // Voxel and octree post-processing (override the scene's "post")
    float bloom = 0.0f, internalScale = 1.0f, sharpness = 0.0f;
    std::string upscalerName;
    PostFlags post;                      // the post flags given, parsed
    std::vector<std::string> postGiven;  // their names
    VoxelSurfaceFlags surfaces;          // voxel scenes
    // Voxel scenes: anti-aliasing and texture filtering (0 / empty: the scene's).
    int samples = 0;
    std::string filter;
    // Voxel scenes, --solver rc: the picture's adaptive samples (-1: the scene's; 0: off).
    int adaptiveSamples = -1;
    // Voxel scenes, --solver path (voxel/path_trace.h); pathGiven: --spp or --max-bounces given.
    int spp = voxel::PathTraceOptions{}.samplesPerPixel;
    int maxBounces = voxel::PathTraceOptions{}.maxBounces;
    std::string stdError;  // --std-error: the per-pixel standard error as EXR
    std::vector<std::string> pathGiven;
    // Voxel scenes, --solver ao (voxel/sky_visibility.h); aoGiven: --ao-rays or --ao-radius given.
    int aoRays = voxel::SkyVisibilityOptions{}.rays;
    double aoRadius = voxel::SkyVisibilityOptions{}.radius;
    std::vector<std::string> aoGiven;
    // Voxel scenes, --solver rc (voxel/radiance_cascades.h): --rc-spacing, and --bounces.
    int rcSpacing = 0;
    bool rcSpacingGiven = false;
};

// Renders what `args` asks for (any scene kind) and returns the exit code.
int runRender(const RenderArgs& args);

}  // namespace luxel::cli
