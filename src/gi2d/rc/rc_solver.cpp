// Vanilla Radiance Cascades: trace each cascade's intervals, merge top-down with bilinear
// interpolation of the 4 upper probes (or the bilinear fix), pre-averaged storage.
#include "luxel/gi2d/rc_solver.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "gi2d/rc/rc_internal.h"
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
    return Ok{};
}

int storedPerProbe(const RcCascade& c, int index) {
    return index == 0 ? 1 : c.rays / 4;
}

}  // namespace rc

using rc::storedPerProbe;
using rc::validate;

namespace {

// Bilinear footprint of a point on a probe grid: 2 indices and weights per axis, clamped.
struct Bilinear {
    int x[2], y[2];
    float wx[2], wy[2];
};

Bilinear bilinearAt(Vec2d p, const RcCascade& grid) {
    Bilinear b;
    const double u = p.x / grid.spacing - 0.5, v = p.y / grid.spacing - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    const float tx = static_cast<float>(u - fu), ty = static_cast<float>(v - fv);
    const int ix = static_cast<int>(fu), iy = static_cast<int>(fv);
    b.x[0] = std::clamp(ix, 0, grid.probesX - 1);
    b.x[1] = std::clamp(ix + 1, 0, grid.probesX - 1);
    b.y[0] = std::clamp(iy, 0, grid.probesY - 1);
    b.y[1] = std::clamp(iy + 1, 0, grid.probesY - 1);
    b.wx[0] = 1.0f - tx;
    b.wx[1] = tx;
    b.wy[0] = 1.0f - ty;
    b.wy[1] = ty;
    return b;
}

Vec2d probeCentre(const RcCascade& c, int px, int py) {
    return {(px + 0.5) * c.spacing, (py + 0.5) * c.spacing};
}

template <typename Tracer>
Result<Image> solveWith(const Tracer& tracer, int w, int h, Rgb sky, const RcOptions& options) {
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

    std::vector<Rgb> upper, current;
    const int lowest = std::max(options.debugCascade, 0);
    for (int i = count - 1; i >= lowest; --i) {
        const RcCascade& c = cascades[i];
        const RcCascade* up = i + 1 < count ? &cascades[i + 1] : nullptr;
        const int stored = storedPerProbe(c, i);
        const int upStored = up ? storedPerProbe(*up, i + 1) : 0;
        const int group = c.rays / stored;  // directions averaged into one stored value
        current.assign(static_cast<std::size_t>(c.probesX) * c.probesY * stored, Rgb());
        const double step = 2.0 * std::numbers::pi / c.rays;

        // Merged radiance of the upper cascade towards direction k of this cascade (the
        // pre-averaged mean of k's 4 children) at upper probe (ux, uy).
        auto upperValue = [&](int ux, int uy, int k) {
            return upper[(static_cast<std::size_t>(uy) * up->probesX + ux) * upStored + k];
        };
        auto mergedRay = [&](Vec2d p, int k) -> Rgb {
            const double angle = (k + 0.5) * step;
            const Vec2d dir{std::cos(angle), std::sin(angle)};
            const Vec2d start = p + dir * c.intervalStart;
            if (up == nullptr) {  // top cascade: the sky lies beyond
                const RaySegment seg = tracer.segment(start, p + dir * c.intervalEnd);
                return seg.radiance + seg.transmittance * sky;
            }
            const Bilinear b = bilinearAt(p, *up);
            if (options.merge == RcMerge::Vanilla) {
                bool leaves = false;
                const RaySegment seg = tracer.segment(start, p + dir * c.intervalEnd, &leaves);
                Rgb beyond = sky;
                if (!leaves) {
                    beyond = Rgb();
                    for (int a = 0; a < 2; ++a) {
                        for (int bb = 0; bb < 2; ++bb) {
                            beyond += upperValue(b.x[a], b.y[bb], k) * (b.wx[a] * b.wy[bb]);
                        }
                    }
                }
                return seg.radiance + seg.transmittance * beyond;
            }
            // Bilinear fix: trace to where each upper probe's interval starts, merge there,
            // then blend the 4 merged results.
            Rgb sum;
            for (int a = 0; a < 2; ++a) {
                for (int bb = 0; bb < 2; ++bb) {
                    const Vec2d q = probeCentre(*up, b.x[a], b.y[bb]);
                    bool leaves = false;
                    const RaySegment seg =
                        tracer.segment(start, q + dir * up->intervalStart, &leaves);
                    const Rgb beyond = leaves ? sky : upperValue(b.x[a], b.y[bb], k);
                    sum += (seg.radiance + seg.transmittance * beyond) * (b.wx[a] * b.wy[bb]);
                }
            }
            return sum;
        };

        parallelForRange(c.probesX * c.probesY, 16, [&](int begin, int end) {
            for (int index = begin; index < end; ++index) {
                const int px = index % c.probesX, py = index / c.probesX;
                const Vec2d p = probeCentre(c, px, py);
                for (int s = 0; s < stored; ++s) {
                    Rgb sum;
                    for (int k = s * group; k < (s + 1) * group; ++k) sum += mergedRay(p, k);
                    current[static_cast<std::size_t>(index) * stored + s] =
                        sum * (1.0f / static_cast<float>(group));
                }
            }
        });
        upper.swap(current);
    }

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
                const Bilinear b = bilinearAt(pixel, c);
                Rgb value;
                for (int a = 0; a < 2; ++a) {
                    for (int bb = 0; bb < 2; ++bb) {
                        value += probeMean(b.x[a], b.y[bb]) * (b.wx[a] * b.wy[bb]);
                    }
                }
                out.setRgb(x, y, value);
            }
        }
    });
    return out;
}

}  // namespace rc

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
        out.push_back(c);
    }
    return out;
}

std::uint64_t estimateRcMemory(int width, int height, const RcOptions& options) {
    std::uint64_t largest = 0;
    const std::vector<RcCascade> cascades = rcCascades(width, height, options);
    for (std::size_t i = 0; i < cascades.size(); ++i) {
        const RcCascade& c = cascades[i];
        largest = std::max<std::uint64_t>(largest,
                                          static_cast<std::uint64_t>(c.probesX) * c.probesY *
                                              storedPerProbe(c, static_cast<int>(i)) * sizeof(Rgb));
    }
    return 2 * largest + imageBytes(width, height, 3);
}

Result<Image> solveRc(const Medium2D& medium, const RcOptions& options) {
    if (Status s = validate(options); !s) return s.error();
    const RayMarcher marcher(medium);
    return solveWith(marcher, medium.width(), medium.height(), medium.boundaryRadiance, options);
}

Result<Image> solveRc(const SdfScene& scene, Rgb boundaryRadiance, const RcOptions& options) {
    return solveWith(scene, scene.width(), scene.height(), boundaryRadiance, options);
}

}  // namespace luxel::gi2d
