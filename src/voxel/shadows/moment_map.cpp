// Moment shadow map construction (rays from the light, supersampling, separable filter, storage)
// and its lookup. The moment formulas are the shared ones (shadow_moments.h), as on the GPU.
#include "luxel/voxel/shadows/moment_map.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "gpu/shaders/shared/shadow_moments.h"
#include "luxel/core/parallel.h"
#include "luxel/voxel/surface_cast.h"

namespace luxel::voxel {
namespace sh = gpu::shared;

LightFrame LightFrame::over(Int3 worldSize, Vec3d towardsLight, int mapSize) {
    LightFrame f;
    f.l = normalize(towardsLight);
    // Any axes square to l: from whichever world axis is least parallel to it.
    const Vec3d helper = std::abs(f.l.y) < 0.9 ? Vec3d{0, 1, 0} : Vec3d{1, 0, 0};
    f.u = normalize(cross(helper, f.l));
    f.v = cross(f.l, f.u);
    double uLo = 1e300, uHi = -1e300, vLo = 1e300, vHi = -1e300, lLo = 1e300, lHi = -1e300;
    for (int c = 0; c < 8; ++c) {
        const Vec3d p{c & 1 ? double(worldSize.x) : 0.0, c & 2 ? double(worldSize.y) : 0.0,
                      c & 4 ? double(worldSize.z) : 0.0};
        uLo = std::min(uLo, dot(p, f.u)), uHi = std::max(uHi, dot(p, f.u));
        vLo = std::min(vLo, dot(p, f.v)), vHi = std::max(vHi, dot(p, f.v));
        lLo = std::min(lLo, dot(p, f.l)), lHi = std::max(lHi, dot(p, f.l));
    }
    // Square texels over the larger extent, centred.
    f.size = std::max(mapSize, 1);
    const double extent = std::max(uHi - uLo, vHi - vLo);
    f.texel = extent / f.size;
    f.uMin = 0.5 * (uLo + uHi) - 0.5 * extent;
    f.vMin = 0.5 * (vLo + vHi) - 0.5 * extent;
    f.top = lHi;
    f.range = std::max(lHi - lLo, 1e-9);
    return f;
}

float momentBiasOf(const ShadowSettings& settings) {
    if (settings.momentBias > 0.0) return static_cast<float>(settings.momentBias);
    return settings.momentStorage == ShadowSettings::MomentStorage::Quantized16
               ? LUXEL_MSM_BIAS_16BIT
               : LUXEL_MSM_BIAS_FP32;
}

namespace {

using Moments = std::array<float, 4>;

// Normalised 1-D filter weights, centre at index `radius`.
std::vector<float> filterKernel(const ShadowSettings& settings) {
    std::vector<float> k;
    const double r = std::max(settings.filterRadius, 0.0);
    if (settings.momentFilter == ShadowSettings::MomentFilter::Box) {
        const int half = static_cast<int>(std::lround(r));
        k.assign(2 * half + 1, 1.0f / (2 * half + 1));
        return k;
    }
    if (r <= 0.0) return {1.0f};
    const int half = static_cast<int>(std::ceil(3.0 * r));
    double sum = 0;
    for (int i = -half; i <= half; ++i) {
        k.push_back(static_cast<float>(std::exp(-0.5 * i * i / (r * r))));
        sum += k.back();
    }
    for (float& w : k) w = static_cast<float>(w / sum);
    return k;
}

// One separable pass (clamp to edge) along x (horizontal) or y.
std::vector<Moments> filterPass(const std::vector<Moments>& in, int size,
                                const std::vector<float>& kernel, bool horizontal) {
    std::vector<Moments> out(in.size());
    const int half = static_cast<int>(kernel.size() / 2);
    parallelForRange(size, 8, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < size; ++x) {
                Moments m{0, 0, 0, 0};
                for (int i = -half; i <= half; ++i) {
                    const int sx = horizontal ? std::clamp(x + i, 0, size - 1) : x;
                    const int sy = horizontal ? y : std::clamp(y + i, 0, size - 1);
                    const Moments& s = in[static_cast<std::size_t>(sy) * size + sx];
                    const float w = kernel[i + half];
                    for (int c = 0; c < 4; ++c) m[c] += w * s[c];
                }
                out[static_cast<std::size_t>(y) * size + x] = m;
            }
        }
    });
    return out;
}

}  // namespace

MomentShadowMap MomentShadowMap::build(const VoxelWorld& world, const TextureSet* textures,
                                       Vec3d towardsLight, const ShadowSettings& settings,
                                       double tanSunRadius) {
    MomentShadowMap map;
    map.tanSun_ = tanSunRadius;
    const LightFrame f = LightFrame::over(world.size(), towardsLight, settings.mapSize);
    map.frame_ = f;
    const int n = f.size;
    std::vector<Moments> raw(static_cast<std::size_t>(n) * n);
    parallelForRange(n, 4, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            for (int x = 0; x < n; ++x) {
                Moments m{0, 0, 0, 0};
                for (int s = 0; s < kSupersample * kSupersample; ++s) {
                    const double su =
                        f.uMin + f.texel * (x + (s % kSupersample + 0.5) / kSupersample);
                    const double sv =
                        f.vMin + f.texel * (y + (s / kSupersample + 0.5) / kSupersample);
                    // From just above the world's top in light space, travelling away from it.
                    const Vec3d origin = f.u * su + f.v * sv + f.l * (f.top + 1.0);
                    const SurfaceHit hit = castToSurface(world, textures, Ray{origin, -f.l});
                    const double z =
                        hit.hit.hit ? std::clamp(f.depth(hit.hit.point), 0.0, 1.0) : 1.0;
                    const sh::vec4 b = sh::momentsOfDepth(static_cast<float>(z));
                    for (int c = 0; c < 4; ++c) m[c] += b[c];
                }
                for (float& c : m) c /= kSupersample * kSupersample;
                raw[static_cast<std::size_t>(y) * n + x] = m;
            }
        }
    });
    if (settings.msmFilter == ShadowSettings::MsmFilter::PenumbraSized) {
        const std::size_t w = static_cast<std::size_t>(n) + 1;
        map.sat_.assign(w * w, {0, 0, 0, 0});
        for (int y = 0; y < n; ++y) {
            std::array<double, 4> row{0, 0, 0, 0};
            for (int x = 0; x < n; ++x) {
                const Moments& m = raw[static_cast<std::size_t>(y) * n + x];
                for (int c = 0; c < 4; ++c) {
                    row[c] += m[c];
                    map.sat_[(y + 1) * w + x + 1][c] = map.sat_[y * w + x + 1][c] + row[c];
                }
            }
        }
    }
    const std::vector<float> kernel = filterKernel(settings);
    if (kernel.size() > 1) {
        raw = filterPass(filterPass(raw, n, kernel, true), n, kernel, false);
    }
    map.quantized_ = settings.momentStorage == ShadowSettings::MomentStorage::Quantized16;
    map.words_.resize(raw.size() * (map.quantized_ ? 2 : 4));
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const Moments& m = raw[i];
        if (map.quantized_) {
            const sh::vec4 q = sh::msmEncodeOptimized(sh::vec4(m[0], m[1], m[2], m[3]));
            map.words_[2 * i] = sh::quantizeUnorm16(q.x) | sh::quantizeUnorm16(q.y) << 16;
            map.words_[2 * i + 1] = sh::quantizeUnorm16(q.z) | sh::quantizeUnorm16(q.w) << 16;
        } else {
            for (int c = 0; c < 4; ++c) map.words_[4 * i + c] = std::bit_cast<std::uint32_t>(m[c]);
        }
    }
    return map;
}

std::array<float, 4> MomentShadowMap::moments(int x, int y) const {
    const std::size_t i = static_cast<std::size_t>(y) * frame_.size + x;
    if (quantized_) {
        const sh::vec4 b = sh::unpackMoments16(words_[2 * i], words_[2 * i + 1]);
        return {b.x, b.y, b.z, b.w};
    }
    return {std::bit_cast<float>(words_[4 * i]), std::bit_cast<float>(words_[4 * i + 1]),
            std::bit_cast<float>(words_[4 * i + 2]), std::bit_cast<float>(words_[4 * i + 3])};
}

std::array<double, 4> MomentShadowMap::boxMoments(double u, double v, double h) const {
    const int n = frame_.size;
    const std::size_t w = static_cast<std::size_t>(n) + 1;
    // The prefix sum at a continuous map position: bilinear between the table's corners.
    auto at = [&](double x, double y) {
        x = std::clamp(x, 0.0, double(n)), y = std::clamp(y, 0.0, double(n));
        const int x0 = std::min(static_cast<int>(x), n - 1),
                  y0 = std::min(static_cast<int>(y), n - 1);
        const double tx = x - x0, ty = y - y0;
        std::array<double, 4> r{};
        for (int c = 0; c < 4; ++c) {
            const double a = sat_[y0 * w + x0][c] * (1 - tx) + sat_[y0 * w + x0 + 1][c] * tx;
            const double b =
                sat_[(y0 + 1) * w + x0][c] * (1 - tx) + sat_[(y0 + 1) * w + x0 + 1][c] * tx;
            r[c] = a * (1 - ty) + b * ty;
        }
        return r;
    };
    const double x0 = std::clamp(u - h, 0.0, double(n)), x1 = std::clamp(u + h, 0.0, double(n));
    const double y0 = std::clamp(v - h, 0.0, double(n)), y1 = std::clamp(v + h, 0.0, double(n));
    const double area = (x1 - x0) * (y1 - y0);
    if (area <= 1e-12) {
        const std::array<float, 4> m = moments(std::clamp(static_cast<int>(u), 0, n - 1),
                                               std::clamp(static_cast<int>(v), 0, n - 1));
        return {m[0], m[1], m[2], m[3]};
    }
    const auto a = at(x1, y1), b = at(x0, y1), c = at(x1, y0), d = at(x0, y0);
    std::array<double, 4> r{};
    for (int k = 0; k < 4; ++k) r[k] = (a[k] - b[k] - c[k] + d[k]) / area;
    return r;
}

namespace {

// The narrowest box, texels: half a texel keeps contact shadows sharp (measured: 0.5 was
// slightly better than 1 on every scene, 1.5 and more lost the gain on the slab test).
constexpr double kMinHalfWidth = 0.5;

// Widest blocker search, texels (every box costs the same with the table): keeps far-away
// blockers of deep receivers from averaging in.
constexpr double kMaxSearchTexels = 64.0;

sh::vec4 toVec4(const std::array<double, 4>& m) {
    return sh::vec4(float(m[0]), float(m[1]), float(m[2]), float(m[3]));
}

}  // namespace

MomentShadowMap::Penumbra MomentShadowMap::penumbra(Vec3d p, const ShadowSettings& settings) const {
    Penumbra out;
    if (sat_.empty()) return out;
    const LightFrame& f = frame_;
    const double mu = (dot(p, f.u) - f.uMin) / f.texel, mv = (dot(p, f.v) - f.vMin) / f.texel;
    const double z = f.depth(p) - settings.depthBias / f.range;
    const double hMin = kMinHalfWidth;
    // Blocker search over the widest penumbra p can have: a blocker at the map's top (depth 0).
    const double hSearch = std::clamp(tanSun_ * z * f.range / f.texel, hMin, kMaxSearchTexels);
    const sh::vec2 blocker =
        sh::msmBlocker(toVec4(boxMoments(mu, mv, hSearch)), float(z), momentBiasOf(settings));
    out.halfWidthTexels = hMin;
    if (blocker.x < 1e-4f) return out;
    out.blocked = true;
    out.blockerDepth = std::max(z - double(blocker.y), 0.0) * f.range;
    out.width = 2.0 * tanSun_ * out.blockerDepth;
    // The box with the area of the blocker-plane disk of radius tan(theta_L) * depth: the
    // lit fraction of the sun is the open fraction of that disk (PCSS, Fernando 2005).
    const double radius = tanSun_ * out.blockerDepth / f.texel;
    out.halfWidthTexels = std::clamp(radius * 0.5 * std::sqrt(3.14159265358979), hMin, hSearch);
    return out;
}

MomentShadowMap::Lookup MomentShadowMap::visibility(Vec3d p, bool vsm,
                                                    const ShadowSettings& settings) const {
    const LightFrame& f = frame_;
    const double mu = (dot(p, f.u) - f.uMin) / f.texel, mv = (dot(p, f.v) - f.vMin) / f.texel;
    Lookup r;
    r.valid = mu >= 0.0 && mv >= 0.0 && mu <= f.size && mv <= f.size;
    if (!r.valid) return r;
    if (!sat_.empty()) {
        const Penumbra pen = penumbra(p, settings);
        const float z = static_cast<float>(f.depth(p) - settings.depthBias / f.range);
        r.visibility =
            sh::momentVisibility(toVec4(boxMoments(mu, mv, pen.halfWidthTexels)), z, vsm,
                                 momentBiasOf(settings), float(settings.lightBleedReduction));
        return r;
    }
    // Bilinear between texel centres, clamped at the edges.
    const double fu = mu - 0.5, fv = mv - 0.5;
    const int x0 = static_cast<int>(std::floor(fu)), y0 = static_cast<int>(std::floor(fv));
    const float tx = static_cast<float>(fu - x0), ty = static_cast<float>(fv - y0);
    sh::vec4 b(0.0f);
    for (int k = 0; k < 4; ++k) {
        const int dx = k & 1, dy = k >> 1;
        const std::array<float, 4> m =
            moments(std::clamp(x0 + dx, 0, f.size - 1), std::clamp(y0 + dy, 0, f.size - 1));
        const float w = (dx ? tx : 1.0f - tx) * (dy ? ty : 1.0f - ty);
        b = b + sh::vec4(m[0], m[1], m[2], m[3]) * w;
    }
    const float z = static_cast<float>(f.depth(p) - settings.depthBias / f.range);
    r.visibility = sh::momentVisibility(b, z, vsm, momentBiasOf(settings),
                                        static_cast<float>(settings.lightBleedReduction));
    return r;
}

}  // namespace luxel::voxel
