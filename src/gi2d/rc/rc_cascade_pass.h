// One cascade of vanilla RC as a unit (docs/algorithms/radiance-cascades-2d.md §2): the CPU pass
// (a template over the interval tracer: the pixel medium's RayMarcher or the analytic SdfScene),
// the GPU pass (shader rc_cascade) with its dispatch builder, both computing every probe's stored
// values of cascade i from cascade i + 1. The per-probe arithmetic is shared with the shader
// (src/gpu/shaders/shared/rc_kernels.h).
#pragma once

#include <vector>

#include "gi2d/rc/rc_internal.h"
#include "luxel/core/parallel.h"
#include "luxel/core/vec.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/ray_march.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gpu/context.h"

#define LUXEL_REAL double
#define LUXEL_REAL2 dvec2
#include "gpu/shaders/shared/rc_kernels.h"
#undef LUXEL_REAL
#undef LUXEL_REAL2

namespace luxel::gi2d::rc {

// Merged radiance of direction k of cascade `c` at probe position p: the interval traced, then
// composited with what lies beyond (`upperValue(ux, uy, k)` reads the upper cascade's stored value
// of direction k at upper probe (ux, uy); `up` is null at the top, where the sky lies beyond).
template <typename Tracer, typename UpperValue>
Rgb mergedRay(const Tracer& tracer, const RcCascade& c, const RcCascade* up, Vec2d p, int k,
              UpperValue&& upperValue, Rgb sky, RcMerge merge) {
    namespace shared = gpu::shared;
    const auto vec = [](shared::dvec2 v) { return Vec2d{v.x, v.y}; };
    const Vec2d dir = vec(shared::rcDirection(k, c.rays));
    const Vec2d start = p + dir * c.intervalStart;
    if (up == nullptr) {  // top cascade: the sky lies beyond
        const RaySegment seg = tracer.segment(start, p + dir * c.intervalEnd);
        return seg.radiance + seg.transmittance * sky;
    }
    const shared::RcBilinear b = shared::rcBilinearAt({p.x - up->offsetX, p.y - up->offsetY},
                                                      up->spacing, up->probesX, up->probesY);
    if (merge == RcMerge::Vanilla) {
        bool leaves = false;
        const RaySegment seg = tracer.segment(start, p + dir * c.intervalEnd, &leaves);
        Rgb beyond = sky;
        if (!leaves) {
            beyond = Rgb();
            for (int a = 0; a < 2; ++a) {
                for (int bb = 0; bb < 2; ++bb) {
                    beyond += upperValue(shared::rcBilinearX(b, a), shared::rcBilinearY(b, bb), k) *
                              shared::rcBilinearWeight(b, a, bb);
                }
            }
        }
        return seg.radiance + seg.transmittance * beyond;
    }
    // Bilinear fix: trace to where each upper probe's interval starts, merge there, then blend
    // the 4 merged results.
    Rgb sum;
    for (int a = 0; a < 2; ++a) {
        for (int bb = 0; bb < 2; ++bb) {
            const int ux = shared::rcBilinearX(b, a), uy = shared::rcBilinearY(b, bb);
            const Vec2d q =
                vec(shared::rcProbeCentre(ux, uy, up->spacing)) + Vec2d{up->offsetX, up->offsetY};
            bool leaves = false;
            const RaySegment seg = tracer.segment(start, q + dir * up->intervalStart, &leaves);
            const Rgb beyond = leaves ? sky : upperValue(ux, uy, k);
            sum += (seg.radiance + seg.transmittance * beyond) * shared::rcBilinearWeight(b, a, bb);
        }
    }
    return sum;
}

// Cascade `i` of `cascades` merged with `upper` (cascade i + 1's stored values; ignored for the
// top cascade): for each probe, the mean merged radiance of each group of directions, probe-major
// ((py * probesX + px) * stored + s). Rays whose interval leaves the canvas see `sky` beyond.
// The exact reference: solveRc runs cascadePassStencil (gi2d/rc/rc_stencil.h) on the pixel
// medium, which gives this pass's result to float rounding.
template <typename Tracer>
std::vector<Rgb> cascadePass(const Tracer& tracer, const std::vector<RcCascade>& cascades, int i,
                             const std::vector<Rgb>& upper, Rgb sky, RcMerge merge) {
    namespace shared = gpu::shared;
    const RcCascade& c = cascades[i];
    const int count = static_cast<int>(cascades.size());
    const RcCascade* up = i + 1 < count ? &cascades[i + 1] : nullptr;
    const int stored = storedPerProbe(c, i);
    const int upStored = up ? storedPerProbe(*up, i + 1) : 0;
    const int group = shared::rcGroup(c.rays, stored);
    std::vector<Rgb> current(static_cast<std::size_t>(c.probesX) * c.probesY * stored);

    // Merged radiance of the upper cascade towards direction k of this cascade (the pre-averaged
    // mean of k's 4 children) at upper probe (ux, uy).
    auto upperValue = [&](int ux, int uy, int k) {
        return upper[(static_cast<std::size_t>(uy) * up->probesX + ux) * upStored + k];
    };

    parallelForRange(c.probesX * c.probesY, 16, [&](int begin, int end) {
        for (int index = begin; index < end; ++index) {
            const int px = index % c.probesX, py = index / c.probesX;
            const shared::dvec2 centre = shared::rcProbeCentre(px, py, c.spacing);
            const Vec2d p = Vec2d{centre.x, centre.y} + Vec2d{c.offsetX, c.offsetY};
            for (int s = 0; s < stored; ++s) {
                Rgb sum;
                for (int k = s * group; k < (s + 1) * group; ++k) {
                    sum += mergedRay(tracer, c, up, p, k, upperValue, sky, merge);
                }
                current[static_cast<std::size_t>(index) * stored + s] =
                    sum * (1.0f / static_cast<float>(group));
            }
        }
    });
    return current;
}

// The dispatch of rc_cascade for cascade i (buffers: medium, upper, current; `upper` null at the
// top).
gpu::Dispatch makeCascadeDispatch(gpu::Program* program, gpu::Buffer* medium, gpu::Buffer* upper,
                                  gpu::Buffer* current, const std::vector<RcCascade>& cascades,
                                  int i, int width, int height, Rgb sky, RcMerge merge);

// cascadePass on the GPU for the pixel medium: uploads the medium and `upper`, runs the pass,
// reads cascade i back into `out`. Returns the pass's GPU time in milliseconds.
Result<double> cascadePassOnGpu(gpu::Context& context, const Medium2D& medium,
                                const std::vector<RcCascade>& cascades, int i,
                                const std::vector<Rgb>& upper, RcMerge merge,
                                std::vector<Rgb>& out);

}  // namespace luxel::gi2d::rc
