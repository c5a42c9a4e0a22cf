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
                                       Vec3d towardsLight, const ShadowSettings& settings) {
    MomentShadowMap map;
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

MomentShadowMap::Lookup MomentShadowMap::visibility(Vec3d p, bool vsm,
                                                    const ShadowSettings& settings) const {
    const LightFrame& f = frame_;
    const double mu = (dot(p, f.u) - f.uMin) / f.texel, mv = (dot(p, f.v) - f.vMin) / f.texel;
    Lookup r;
    r.valid = mu >= 0.0 && mv >= 0.0 && mu <= f.size && mv <= f.size;
    if (!r.valid) return r;
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
