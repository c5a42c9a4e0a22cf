// Command-line options of luxel-view, parsed without touching SDL so they can be unit-tested.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "luxel/core/error.h"
#include "luxel/gi2d/solver_choice.h"
#include "luxel/gpu/backend_policy.h"
#include "luxel/voxel/path_trace.h"
#include "luxel/voxel/sky_visibility.h"
#include "progressive_path.h"
#include "voxel_solver.h"

namespace luxel::viewer {

struct ViewerOptions {
    std::string scene;    // a 2D scene, a voxel scene (type "voxel") or an octree (type "octree")
    int windowWidth = 0;  // 0: chosen from the scene
    int windowHeight = 0;
    int internalWidth = 0;  // 0: from internalScale
    int internalHeight = 0;
    float internalScale =
        0.0f;  // 0: the mode's default (2D: of the canvas; voxel, octree: of the window)
    gpu::Backend backend = gpu::Backend::Auto;    // --backend auto | cpu | gpu
    std::string device;                           // Vulkan device index or name part
    gi2d::Solver2D solver = gi2d::Solver2D::Hrc;  // 2D: --solver hrc | rc | reference
    bool solver2DGiven = false;                   // --solver named a 2D solver
    // Voxel scenes: --solver raycast | ao | path (the names of `luxel render --solver`).
    std::optional<VoxelSolver> voxelSolver;
    // Voxel scenes: the path tracer (--spp: where it stops, --max-bounces, --seed) and sky
    // visibility (--ao-rays, --ao-radius, --seed), whichever solver starts.
    voxel::PathTraceOptions path{.samplesPerPixel = kDefaultViewerPathSamples};
    voxel::SkyVisibilityOptions ao;
    std::vector<std::string> voxelFlagsGiven;          // which of those flags were given
    gi2d::RcMerge merge = gi2d::RcMerge::BilinearFix;  // 2D RC: --merge vanilla | bilinear-fix
    float exposure = 0.0f;                             // stops
    std::string script;                                // timed input events (docs/viewer.md)
    int recordFrames = 0;                              // --record N
    std::string recordDir = "frames";
    std::string savePath;  // paint mode saves here (default: SCENE stem + ".painted.json")
    int threads = 0;       // solver threads (0: all)
    int voxFrame = -1;     // MagicaVoxel worlds: the animation frame (-1: the scene's, else 0)
    // Without --internal-size/--internal-scale the internal size adapts to keep this frame rate
    // (0: keep the mode's default size).
    double targetFps = 15.0;
    bool hideOverlay = false;
};

// Parses argv. Returns the options, or an Error whose message is the problem (or, for --help,
// the usage text with `helpRequested` set).
struct ParsedOptions {
    ViewerOptions options;
    bool helpRequested = false;
    std::string helpText;
};
Result<ParsedOptions> parseViewerOptions(const std::vector<std::string>& args);

// "640x480" -> {640, 480} (parseImageSize); fails for anything else or sides outside
// 1..kMaxImageSide.
Result<std::pair<int, int>> parseWindowSize(const std::string& text, const std::string& option);

}  // namespace luxel::viewer
