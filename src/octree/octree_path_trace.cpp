#include "luxel/octree/octree_path_trace.h"

#include <cmath>
#include <numbers>

#include "luxel/core/parallel.h"
#include "luxel/core/rng.h"
#include "octree/octree_access.h"
#include "octree/octree_render_params.h"

namespace luxel::octree {
namespace {

namespace shared = gpu::shared;
using shared::dvec3;

double extinction(std::uint32_t value, const shared::OctreeRenderParams& p) {
    const double a = shared::octreeAlpha(value, p);
    return a >= 1.0 ? 1e9 : -std::log(1.0 - a);
}

// The distance along o + t d (d unit) at which the optical depth reaches `depth`, or +inf when the
// ray leaves the medium first; `entry` receives the colour index of the leaf there.
double freeFlight(const OctreeArrays& tree, const shared::OctreeRenderParams& p, dvec3 o, dvec3 d,
                  double depth, std::uint32_t& entry) {
    shared::OctreeRay r;
    if (!shared::octreeRayStart(r, int(p.depth), shared::octreeParamsSize(p), o, d,
                                std::numeric_limits<double>::infinity())) {
        return std::numeric_limits<double>::infinity();
    }
    for (int steps = 0; steps < int(p.stepCap); ++steps) {
        const shared::OctreeLeaf leaf =
            shared::octreeLocate(tree, int(p.depth), r.cursor, r.walk.cell);
        if (leaf.value > 0u) {
            const double sigma = extinction(leaf.value, p);
            const double t0 = r.walk.t, t1 = shared::octreeLeafExitT(r, leaf);
            if (sigma * (t1 - t0) >= depth) {
                entry = shared::octreeColourIndex(tree, int(p.depth), r.walk.cell, leaf.entry);
                return t0 + depth / sigma;
            }
            depth -= sigma * (t1 - t0);
        }
        if (!shared::octreeRayLeave(r, leaf, std::numeric_limits<double>::infinity())) break;
    }
    return std::numeric_limits<double>::infinity();
}

// A direction scattered from `forward` by the Henyey-Greenstein phase function.
dvec3 sampleHG(dvec3 forward, double g, double u, double v) {
    double cosTheta;
    if (std::fabs(g) < 1e-4) {
        cosTheta = 1.0 - 2.0 * u;
    } else {
        const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
        cosTheta = (1.0 + g * g - s * s) / (2.0 * g);
    }
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * std::numbers::pi * v;
    const dvec3 helper = std::fabs(forward.x) > 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0);
    const dvec3 t = shared::normalize(shared::cross(forward, helper));
    const dvec3 b = shared::cross(forward, t);
    return shared::normalize(forward * cosTheta + t * (sinTheta * std::cos(phi)) +
                             b * (sinTheta * std::sin(phi)));
}

}  // namespace

Result<Image> pathTraceOctree(const Octree& tree, const voxel::Camera& camera,
                              const OctreeRenderOptions& medium, const PathTraceOptions& options) {
    if (Status s = validateRenderOptions(medium); !s) return s.error();
    if (options.samplesPerPixel < 1 || options.maxScatterings < 1) {
        return Error("path trace: samples per pixel and max scatterings must be at least 1");
    }
    const shared::OctreeRenderParams p = renderParams(tree, camera, medium);
    const OctreeArrays arrays = arraysOf(tree);
    const dvec3 sun(p.sunX, p.sunY, p.sunZ);
    const dvec3 sunRadiance(p.sunR, p.sunG, p.sunB);
    Image image(camera.width(), camera.height(), 3);
    parallelForRange(camera.height(), 1, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            for (int x = 0; x < camera.width(); ++x) {
                Pcg32 rng(hashSeed(options.seed, static_cast<std::uint64_t>(x),
                                   static_cast<std::uint64_t>(y)));
                dvec3 sum(0.0);
                for (int s = 0; s < options.samplesPerPixel; ++s) {
                    // Through the pixel centre, as the renderer samples: the same measurement.
                    const voxel::Ray primary = camera.primaryRay(x, y);
                    dvec3 o(primary.origin.x, primary.origin.y, primary.origin.z);
                    dvec3 d(primary.direction.x, primary.direction.y, primary.direction.z);
                    dvec3 throughput(1.0);
                    for (int bounce = 0; bounce < options.maxScatterings; ++bounce) {
                        std::uint32_t entry = 0;
                        const double depth = -std::log(1.0 - rng.nextDouble());
                        const double t = freeFlight(arrays, p, o, d, depth, entry);
                        if (!std::isfinite(t)) break;  // left the medium: black sky
                        o = o + d * t;
                        const shared::vec3 c = shared::octreeLeafColour(arrays, entry);
                        throughput = throughput * dvec3(c.x, c.y, c.z) * double(medium.albedo);
                        // Next-event estimation toward the sun.
                        const double sunT = shared::octreeTransmittance(
                            arrays, p, o, sun, std::numeric_limits<double>::infinity());
                        const double phase =
                            shared::octreePhaseHG(float(shared::dot(d, sun)), medium.phaseG);
                        sum = sum + throughput * sunRadiance * (phase * sunT);
                        d = sampleHG(d, medium.phaseG, rng.nextDouble(), rng.nextDouble());
                    }
                }
                const double n = options.samplesPerPixel;
                image.setRgb(x, y, Rgb(float(sum.x / n), float(sum.y / n), float(sum.z / n)));
            }
        }
    });
    return image;
}

}  // namespace luxel::octree
