// Render memory estimates shared by `luxel render` and `luxel info` (render_memory.h).
#include "commands/render_memory.h"

#include <string>

#include "luxel/core/image.h"
#include "luxel/core/image_rows.h"
#include "luxel/core/memory.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/ray_march.h"
#include "luxel/post/frame_memory.h"
#include "luxel/post/upscale.h"

namespace luxel::cli {

Memory2D estimate2D(int width, int height, gi2d::Solver2D solver, const gi2d::RcOptions& rc,
                    bool bounces) {
    Memory2D m;
    m.medium = gi2d::mediumBytes(width, height);
    switch (solver) {
        case gi2d::Solver2D::Reference:
            m.solver = gi2d::RayMarcher::bytesFor(width, height) + imageBytes(width, height, 3);
            break;
        case gi2d::Solver2D::Hrc:
            m.solver = gi2d::estimateHrcMemory(width, height).total();
            break;
        case gi2d::Solver2D::Rc:
            m.solver = gi2d::estimateRcMemory(width, height, rc);
            break;
    }
    // The fluence; the brightest channel of each pixel for --exposure auto; the writers' strips
    // (two files of a strip of floats and of 8-bit rows, the light sources' strip for the
    // clipping count), counted as 4 strips of 4-channel floats.
    m.outputs = imageBytes(width, height, 3) + imageBytes(width, height, 1) +
                4 * imageBytes(width, kImageStripRows, 4);
    // solveWithBounces: scattering + reflectance, the re-lit medium copy, the next source and the
    // previous fluence while the next one is solved.
    if (bounces) m.bounce = 4 * imageBytes(width, height, 3) + gi2d::mediumBytes(width, height);
    return m;
}

std::uint64_t frameBytes(int width, int height, const post::PostOptions& post, bool gpu) {
    const ImageSize output{width, height};
    const ImageSize internal = post.internalScale < 1.0f
                                   ? ImageSize{post::internalSide(width, post.internalScale),
                                               post::internalSide(height, post.internalScale)}
                                   : output;
    std::uint64_t bytes = post::finishedFrameBytes(internal, output, post);
    if (gpu) {
        bytes += post::kGpuDownloadBytesPerPixel * static_cast<std::uint64_t>(internal.width) *
                 static_cast<std::uint64_t>(internal.height);
    }
    return bytes;
}

Status checkRenderMemory(int width, int height, std::uint64_t needed, const std::string& detail) {
    return checkMemory(
        needed, "rendering " + std::to_string(width) + "x" + std::to_string(height) + detail);
}

}  // namespace luxel::cli
