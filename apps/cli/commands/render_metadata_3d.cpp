// The provenance of voxel and octree renders: what shaded them and how (docs/image-metadata.md).
#include "commands/render_outputs.h"
#include "luxel/gpu/context.h"
#include "luxel/octree/octree_render.h"
#include "luxel/post/post_options.h"
#include "luxel/voxel/render_image.h"
#include "luxel/voxel/shadows/sun_visibility.h"
#include "luxel/voxel/texture_set.h"

namespace luxel::cli {
namespace {

void describeRun(ImageMetadata& m, const post::PostOptions& post, const gpu::Context* context,
                 double renderSeconds) {
    setMetadata(m, "luxel.backend", context != nullptr ? "gpu" : "cpu");
    if (context != nullptr) setMetadata(m, "luxel.device", context->device().name);
    setNumber(m, "luxel.internal_scale", post.internalScale);
    if (post.internalScale < 1.0f)
        setMetadata(m, "luxel.upscaler", post::upscalerName(post.upscaler));
    setNumber(m, "luxel.sharpness", post.sharpness);
    setNumber(m, "luxel.bloom", post.bloom.strength);
    setNumber(m, "luxel.render.seconds", renderSeconds);
}

}  // namespace

ImageMetadata voxelMetadata(const std::string& scenePath, const voxel::ShadeOptions& shading,
                            const post::PostOptions& post, int width, int height,
                            const gpu::Context* context, double renderSeconds) {
    ImageMetadata m = renderMetadata(scenePath, "voxel", width, height);
    const bool physical = shading.lighting == voxel::ShadeOptions::Lighting::Physical;
    setMetadata(m, "luxel.lighting", physical ? "physical" : "classic");
    setMetadata(m, "luxel.shadows",
                !shading.shadows ? "off"
                : physical       ? voxel::shadowMethodName(shading.shadowSettings.method)
                                 : "hard");
    setNumber(m, "luxel.samples", voxel::samplesPerPixel(shading));
    setMetadata(m, "luxel.filter", voxel::textureFilterName(shading.textureFilter));
    setNumber(m, "luxel.reflections", shading.maxReflections);
    describeRun(m, post, context, renderSeconds);
    return m;
}

ImageMetadata octreeMetadata(const std::string& scenePath, const std::string& source,
                             const octree::OctreeRenderOptions& render,
                             const post::PostOptions& post, int width, int height,
                             const gpu::Context* context, double renderSeconds) {
    ImageMetadata m = renderMetadata(scenePath, "octree", width, height);
    setMetadata(m, "luxel.octree.source", source);
    setMetadata(m, "luxel.octree.mode", octree::octreeModeName(render.mode));
    setMetadata(m, "luxel.shadows", render.shadows ? "on" : "off");
    setNumber(m, "luxel.shadow_samples", render.shadowSamples);
    describeRun(m, post, context, renderSeconds);
    return m;
}

}  // namespace luxel::cli
