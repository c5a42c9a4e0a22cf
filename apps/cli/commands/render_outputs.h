// What `luxel render` writes besides pixels: provenance metadata in every image, the exposure
// (`--exposure auto` included) and the warning for a blown-out display image. Shared by the 2D,
// voxel and octree renders.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/core/image_metadata.h"
#include "luxel/core/tonemap.h"
#include "luxel/gpu/fwd.h"

namespace luxel::voxel {
struct ShadeOptions;
}
namespace luxel::octree {
struct OctreeRenderOptions;
}
namespace luxel::post {
struct PostOptions;
}

namespace luxel::cli {

// `--exposure`: a number of stops in [-64, 64], or "auto" (luxel/core/tonemap.h:
// autoExposureStops). Unset when the text is empty.
struct ExposureFlag {
    std::optional<float> stops;
    bool automatic = false;
};
Result<ExposureFlag> parseExposureFlag(const std::string& text);

// The metadata every render carries (docs/image-metadata.md): luxel.version, luxel.date (UTC),
// luxel.scene, luxel.scene.fnv1a64 (of the scene file's bytes), luxel.solver, luxel.canvas.
ImageMetadata renderMetadata(const std::string& scenePath, const std::string& solver, int width,
                             int height);
// Adds "key" = value with up to 6 significant digits.
void setNumber(ImageMetadata& metadata, const std::string& key, double value);

// The metadata of voxel and octree renders: renderMetadata, the shading and post settings, the
// backend (context null: the CPU) and the render time (render_metadata_3d.cpp).
ImageMetadata voxelMetadata(const std::string& scenePath, const voxel::ShadeOptions& shading,
                            const post::PostOptions& post, int width, int height,
                            const gpu::Context* context, double renderSeconds);
ImageMetadata octreeMetadata(const std::string& scenePath, const std::string& source,
                             const octree::OctreeRenderOptions& render,
                             const post::PostOptions& post, int width, int height,
                             const gpu::Context* context, double renderSeconds);

// The images of one render and how they are written.
struct RenderImages {
    std::string out, png;               // --out (.exr linear, .png tonemapped) and --png; "" = none
    const Image* linear = nullptr;      // fluence or radiance: --out
    const char* linearName = "";        // "fluence" or "radiance", for luxel.content
    const Image* displayHdr = nullptr;  // what --png shows, before tone mapping
    // Added to displayHdr pixel by pixel when set (the 2D render's light sources): the sum is made
    // strip by strip, never as a whole image.
    const Image* displayAdd = nullptr;
    ToneMapSettings tone;  // exposure and curve (the exposure settled below)
    bool autoExposure = false;
    bool quiet = false;
    ImageMetadata metadata;  // renderMetadata and the solver's settings
    // Marks drawn on the tonemapped --png (optional), strip by strip: canvas rows [y0, y1) as RGB
    // floats, `width` pixels a row.
    std::function<void(float* rows, int width, int y0, int y1)> drawOnDisplay;
    // The light sources' own radiance (optional): pixels where it alone shows white are lights
    // seen directly, which the clipping warning does not count.
    const Image* lightSources = nullptr;
};

// Settles --exposure auto from images.displayHdr (prints the stops chosen unless quiet), adds the
// tone settings to the metadata, tonemaps, writes --out and --png together (luxel/core/image_io.h:
// writeImages), each with the metadata and luxel.content, and warns about a blown-out picture.
// Tone mapping, the display sum and the warning's count run strip by strip as the files are
// written: nothing the size of the image is allocated here.
Status writeRenderImages(RenderImages images);

// The fraction of display pixels at white (light sources not counted) above which `luxel render`
// warns.
inline constexpr double kClippedWarningFraction = 0.05;

}  // namespace luxel::cli
