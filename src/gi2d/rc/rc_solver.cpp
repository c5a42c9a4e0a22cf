// Vanilla Radiance Cascades: trace each cascade's intervals, merge top-down with bilinear
// interpolation of the 4 upper probes (or the bilinear fix), pre-averaged storage.
#include "luxel/gi2d/rc_solver.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "gi2d/rc/rc_cascade_pass.h"
#include "gi2d/rc/rc_internal.h"
#include "gi2d/rc/rc_stencil.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d {
namespace rc {

Status validate(const RcOptions& o) {
    if (o.probeSpacing < 1 || o.probeSpacing > 64) {
        return Error("RC probe spacing must be in 1..64, got " + std::to_string(o.probeSpacing));
    }
    if (o.baseRays < 1 || o.baseRays > 1024) {
        return Error("RC base rays must be in 1..1024, got " + std::to_string(o.baseRays));
    }
    if (!(o.baseInterval > 0.0) || !std::isfinite(o.baseInterval) || o.baseInterval > 1e5) {
        return Error("RC base interval must be a positive length in pixels, got " +
                     std::to_string(o.baseInterval));
    }
    if (o.maxCascades < 0 || o.maxCascades > 16) {
        return Error("RC max cascades must be in 0..16, got " + std::to_string(o.maxCascades));
    }
    if (!(o.jitterX >= 0.0 && o.jitterX < 1.0 && o.jitterY >= 0.0 && o.jitterY < 1.0)) {
        return Error("RC probe jitter must be in [0, 1) of a probe spacing, got " +
                     std::to_string(o.jitterX) + ", " + std::to_string(o.jitterY));
    }
    if (o.jitters < 1 || o.jitters > 256) {
        return Error("RC jitters must be in 1..256, got " + std::to_string(o.jitters));
    }
    return Ok{};
}

int storedPerProbe(const RcCascade& c, int index) {
    return index == 0 ? 1 : c.rays / 4;
}

}  // namespace rc

using rc::storedPerProbe;
using rc::validate;

namespace {

// Solves with `pass(cascades, i, upper)`, top-down; the pass's stored values are probe-major
// or, with `slotMajor`, slot-major.
template <typename Pass>
Result<Image> solveWith(int w, int h, const RcOptions& options, bool slotMajor, Pass&& pass) {
    if (Status s = validate(options); !s) return s.error();
    const std::vector<RcCascade> cascades = rcCascades(w, h, options);
    const int count = static_cast<int>(cascades.size());
    if (options.debugCascade >= count) {
        return Error("debug cascade " + std::to_string(options.debugCascade) +
                     " does not exist (this size has " + std::to_string(count) + ")");
    }
    if (Status s = checkMemory(estimateRcMemory(w, h, options),
                               "RC at " + std::to_string(w) + "x" + std::to_string(h));
        !s) {
        return s.error();
    }

    std::vector<Rgb> upper;
    const int lowest = std::max(options.debugCascade, 0);
    for (int i = count - 1; i >= lowest; --i) upper = pass(cascades, i, upper);
    if (slotMajor) upper = rc::toProbeMajor(upper, storedPerProbe(cascades[lowest], lowest));

    return rc::readOut(cascades[lowest], lowest, upper, w, h, options.debugCascade >= 0);
}

}  // namespace

namespace rc {

Image readOut(const RcCascade& c, int level, const std::vector<Rgb>& upper, int w, int h,
              bool nearestProbe) {
    const int stored = storedPerProbe(c, level);
    auto probeMean = [&](int px, int py) {
        Rgb sum;
        for (int s = 0; s < stored; ++s) {
            sum += upper[(static_cast<std::size_t>(py) * c.probesX + px) * stored + s];
        }
        return sum * (1.0f / static_cast<float>(stored));
    };
    Image out(w, h, 3);
    if (!nearestProbe && stored == 1 && c.spacing == 1.0 && c.offsetX == 0 && c.offsetY == 0 &&
        c.probesX == w && c.probesY == h) {
        // A probe on every pixel centre: the bilinear weights are 1 and 0, the value the probe's.
        parallelForRange(h, 8, [&](int begin, int end) {
            for (int y = begin; y < end; ++y) {
                for (int x = 0; x < w; ++x) {
                    out.setRgb(x, y, upper[static_cast<std::size_t>(y) * w + x]);
                }
            }
        });
        return out;
    }
    parallelForRange(h, 8, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < w; ++x) {
                const Vec2d pixel{x + 0.5, y + 0.5};
                if (nearestProbe) {
                    const int px = std::min(static_cast<int>(pixel.x / c.spacing), c.probesX - 1);
                    const int py = std::min(static_cast<int>(pixel.y / c.spacing), c.probesY - 1);
                    out.setRgb(x, y, probeMean(px, py));
                    continue;
                }
                const gpu::shared::RcBilinear b = gpu::shared::rcBilinearAt(
                    {pixel.x - c.offsetX, pixel.y - c.offsetY}, c.spacing, c.probesX, c.probesY);
                Rgb value;
                for (int a = 0; a < 2; ++a) {
                    for (int bb = 0; bb < 2; ++bb) {
                        value += probeMean(gpu::shared::rcBilinearX(b, a),
                                           gpu::shared::rcBilinearY(b, bb)) *
                                 gpu::shared::rcBilinearWeight(b, a, bb);
                    }
                }
                out.setRgb(x, y, value);
            }
        }
    });
    return out;
}

}  // namespace rc

void rcJitterShift(int r, double& x, double& y) {
    x = std::fmod(0.5 + r * 0.7548776662466927, 1.0);
    y = std::fmod(0.5 + r * 0.5698402909980532, 1.0);
}

std::vector<RcCascade> rcCascades(int width, int height, const RcOptions& options) {
    const double diagonal = std::hypot(width, height);
    int count =
        static_cast<int>(std::ceil(std::log(diagonal / options.baseInterval) / std::log(4.0))) + 1;
    count = std::max(count, 1);
    if (options.maxCascades > 0) count = std::min(count, options.maxCascades);
    std::vector<RcCascade> out;
    for (int i = 0; i < count; ++i) {
        const double scale = std::pow(4.0, i);
        const double spacing = options.probeSpacing * std::pow(2.0, i);
        RcCascade c;
        c.spacing = spacing;
        c.probesX = static_cast<int>(std::ceil(width / spacing));
        c.probesY = static_cast<int>(std::ceil(height / spacing));
        c.rays = options.baseRays * static_cast<int>(scale);
        c.intervalStart = options.baseInterval * (scale - 1.0) / 3.0;
        c.intervalEnd = c.intervalStart + options.baseInterval * scale;
        // Jitter shifts the grids above cascade 0 back by up to one spacing, with one probe more
        // per row and column so they still cover the canvas. Cascade 0 stays on the pixels: its
        // probes are read out directly, and shifting them would blur the image.
        if (i > 0 && (options.jitterX != 0 || options.jitterY != 0)) {
            c.probesX += 1;
            c.probesY += 1;
            c.offsetX = (options.jitterX - 1.0) * spacing;
            c.offsetY = (options.jitterY - 1.0) * spacing;
        }
        out.push_back(c);
    }
    return out;
}

std::uint64_t estimateRcMemory(int width, int height, const RcOptions& options) {
    std::uint64_t largest = 0;
    RcOptions shifted = options;  // jittered grids have one probe more per row and column
    if (options.jitters > 1) shifted.jitterX = shifted.jitterY = 0.5;
    const std::vector<RcCascade> cascades = rcCascades(width, height, shifted);
    for (std::size_t i = 0; i < cascades.size(); ++i) {
        const RcCascade& c = cascades[i];
        largest = std::max<std::uint64_t>(largest,
                                          static_cast<std::uint64_t>(c.probesX) * c.probesY *
                                              storedPerProbe(c, static_cast<int>(i)) * sizeof(Rgb));
    }
    // The stencil walks (docs/algorithms/radiance-cascades-2d.md §8): the medium's palette and
    // the largest cascade's absorption planes.
    std::uint64_t planes = 0;
    for (std::size_t i = 0; i < cascades.size(); ++i) {
        const bool fix = options.merge == RcMerge::BilinearFix && i + 1 < cascades.size();
        planes = std::max(planes, rc::stencilPassBytes(width, height, cascades[i], fix));
    }
    const std::uint64_t stencils = rc::StencilMedium::bytesFor(width, height) + planes;
    // The output, and the running sum when several jittered solves are averaged.
    const std::uint64_t images = options.jitters > 1 ? 2 : 1;
    return 2 * largest + stencils + images * imageBytes(width, height, 3);
}

Result<Image> solveRc(const Medium2D& medium, const RcOptions& options) {
    if (Status s = validate(options); !s) return s.error();
    if (Status s = checkMemory(
            estimateRcMemory(medium.width(), medium.height(), options),
            "RC at " + std::to_string(medium.width()) + "x" + std::to_string(medium.height()));
        !s) {
        return s.error();
    }
    const RayMarcher marcher(medium);
    const rc::StencilMedium stencilMedium(medium);
    return rc::averageJitters(options, [&](const RcOptions& one) {
        return solveWith(
            medium.width(), medium.height(), one, true,
            [&](const std::vector<RcCascade>& cascades, int i, const std::vector<Rgb>& upper) {
                return rc::cascadePassStencil(marcher, stencilMedium, cascades, i, upper,
                                              medium.boundaryRadiance, one.merge);
            });
    });
}

Result<Image> solveRc(const SdfScene& scene, Rgb boundaryRadiance, const RcOptions& options) {
    if (Status s = validate(options); !s) return s.error();
    return rc::averageJitters(options, [&](const RcOptions& one) {
        return solveWith(
            scene.width(), scene.height(), one, false,
            [&](const std::vector<RcCascade>& cascades, int i, const std::vector<Rgb>& upper) {
                return rc::cascadePass(scene, cascades, i, upper, boundaryRadiance, one.merge);
            });
    });
}

}  // namespace luxel::gi2d
