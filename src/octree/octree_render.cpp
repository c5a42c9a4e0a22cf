#include "luxel/octree/octree_render.h"

#include <cmath>
#include <numbers>
#include <string>

#include "luxel/core/parallel.h"
#include "luxel/octree/octree_light_cache.h"
#include "luxel/octree/octree_tiles.h"
#include "octree/octree_access.h"
#include "octree/octree_render_params.h"

namespace luxel::octree {

namespace shared = gpu::shared;

Result<OctreeMode> parseOctreeMode(std::string_view text, std::string_view what) {
    for (OctreeMode m :
         {OctreeMode::Surface, OctreeMode::Volume, OctreeMode::Additive, OctreeMode::Tiles}) {
        if (text == octreeModeName(m)) return m;
    }
    std::string message(what);
    message += " '";
    message += text;
    message += "' is not one of: surface, volume, additive, tiles";
    return Error(message);
}

const char* octreeModeName(OctreeMode mode) {
    switch (mode) {
        case OctreeMode::Surface:
            return "surface";
        case OctreeMode::Volume:
            return "volume";
        case OctreeMode::Additive:
            return "additive";
        case OctreeMode::Tiles:
            return "tiles";
    }
    return "surface";
}

Status validateRenderOptions(const OctreeRenderOptions& o) {
    auto bad = [](const std::string& what) { return Error("octree render: " + what); };
    if (o.threshold < 1) return bad("threshold must be in 1..255");
    if (!(o.opacityScale >= 0.0f && o.opacityScale <= 1e6f)) {
        return bad("opacity scale must be in 0..1e6");
    }
    const Vec3 s = o.sunDirection;
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z) ||
        s.x * s.x + s.y * s.y + s.z * s.z < 1e-12f) {
        return bad("sun direction must be finite and non-zero");
    }
    for (const Rgb& c : {o.sun, o.sky}) {
        for (int i = 0; i < 3; ++i) {
            if (!(c[i] >= 0.0f && c[i] <= 1e6f)) return bad("sun and sky must be in 0..1e6");
        }
    }
    if (!(o.ambient >= 0.0f && o.ambient <= 100.0f)) return bad("ambient must be in 0..100");
    if (!(o.sunRadiusDegrees >= 0.0f && o.sunRadiusDegrees <= 45.0f)) {
        return bad("sun radius must be in 0..45 degrees");
    }
    if (o.shadowSamples < 1 || o.shadowSamples > 1024) return bad("shadow samples must be 1..1024");
    if (!(o.albedo >= 0.0f && o.albedo <= 1.0f)) return bad("albedo must be in 0..1");
    if (!(o.phaseG > -1.0f && o.phaseG < 1.0f)) return bad("phase g must be in (-1, 1)");
    if (o.octaves < 1 || o.octaves > 8) return bad("octaves must be in 1..8");
    if (!(o.octaveWeight >= 0.0f && o.octaveWeight <= 1.0f)) {
        return bad("octave weight must be in 0..1");
    }
    if (!(o.windowLow < o.windowHigh)) {
        return bad("opacity window must have its low end below its high end");
    }
    if (o.lightCacheStride != kLightCacheAuto &&
        (o.lightCacheStride < 0 || o.lightCacheStride > 4096)) {
        return bad("light cache stride must be auto (-1) or 0..4096");
    }
    return Ok{};
}

shared::OctreeRenderParams mediumParams(const Octree& tree, const OctreeRenderOptions& o) {
    shared::OctreeRenderParams p{};
    const Vec3 sun = normalize(o.sunDirection);
    const Int3 size = tree.extent();
    p.sunRadius = o.sunRadiusDegrees * std::numbers::pi_v<float> / 180.0f;
    p.opacityScale = o.opacityScale;
    p.windowLow = o.windowLow;
    p.windowHigh = o.windowHigh;
    p.albedo = o.albedo;
    p.phaseG = o.phaseG;
    p.sunX = sun.x, p.sunY = sun.y, p.sunZ = sun.z;
    p.ambient = o.ambient;
    p.sunR = o.sun.r, p.sunG = o.sun.g, p.sunB = o.sun.b;
    p.octaveWeight = o.octaveWeight;
    p.skyR = o.sky.r, p.skyG = o.sky.g, p.skyB = o.sky.b;
    const bool cached = o.mode == OctreeMode::Volume && o.scattering;
    p.lightStride =
        static_cast<std::uint32_t>(cached ? lightCacheStride(size, o.lightCacheStride) : 0);
    p.depth = static_cast<std::uint32_t>(tree.depth);
    p.mode = static_cast<std::uint32_t>(o.mode);
    p.sizeX = static_cast<std::uint32_t>(size.x);
    p.sizeY = static_cast<std::uint32_t>(size.y);
    p.sizeZ = static_cast<std::uint32_t>(size.z);
    p.threshold = o.threshold;
    p.shadowSamples = static_cast<std::uint32_t>(o.shadowSamples);
    p.flags = (o.shadows ? LUXEL_OCTREE_SHADOWS : 0u) |
              (o.scattering ? LUXEL_OCTREE_SCATTERING : 0u) |
              (tree.hasColours() ? LUXEL_OCTREE_COLOURS : 0u) |
              (tree.leafOrder() ? LUXEL_OCTREE_LEAF_ORDER : 0u);
    p.octaves = static_cast<std::uint32_t>(o.octaves);
    p.stepCap = static_cast<std::uint32_t>(3 * (size.x + size.y + size.z));
    return p;
}

shared::OctreeRenderParams renderParams(const Octree& tree, const voxel::Camera& camera,
                                        const OctreeRenderOptions& o) {
    shared::OctreeRenderParams p = mediumParams(tree, o);
    const Vec3d pos = camera.position();
    const double tanHalf = std::tan(camera.fovYDegrees() * std::numbers::pi / 360.0);
    const double aspect = static_cast<double>(camera.width()) / camera.height();
    const Vec3d f = camera.forward(), r = camera.right() * (tanHalf * aspect),
                u = camera.up() * tanHalf;
    p.originX = float(pos.x), p.originY = float(pos.y), p.originZ = float(pos.z);
    p.forwardX = float(f.x), p.forwardY = float(f.y), p.forwardZ = float(f.z);
    p.rightX = float(r.x), p.rightY = float(r.y), p.rightZ = float(r.z);
    p.upX = float(u.x), p.upY = float(u.y), p.upZ = float(u.z);
    p.width = static_cast<std::uint32_t>(camera.width());
    p.height = static_cast<std::uint32_t>(camera.height());
    return p;
}

Result<Image> renderOctree(const Octree& tree, const voxel::Camera& camera,
                           const OctreeRenderOptions& options, OctreeLightCache* lightCache) {
    if (Status s = validateRenderOptions(options); !s) return s.error();
    if (options.mode == OctreeMode::Tiles) {
        auto tiles = renderOctreeTiles(tree, camera, options, {});
        if (!tiles) return tiles.error();
        return std::move(tiles->image);
    }
    const shared::OctreeRenderParams p = renderParams(tree, camera, options);
    OctreeArrays arrays = arraysOf(tree);
    OctreeLightCache local;
    OctreeLightCache& cache = lightCache ? *lightCache : local;
    if (p.lightStride != 0) {
        if (!cache.matches(tree, options)) {
            auto filled = fillLightCache(tree, options);
            if (!filled) return filled.error();
            cache = std::move(*filled);
        }
        arrays.lightCache = cache.values.data();
    }
    Image image(camera.width(), camera.height(), 3);
    parallelForRange(camera.height(), 1, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < camera.width(); ++x) {
                const shared::vec3 c = shared::octreeRenderPixel(arrays, p, x, y);
                image.setRgb(x, y, Rgb(c.x, c.y, c.z));
            }
        }
    });
    return image;
}

}  // namespace luxel::octree
