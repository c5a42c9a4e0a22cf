// The compact lights' exact direct light (§12.5): fans from their point sources for the far
// pixels, a gather across each light's cone for the near ones, under a budget of work.
#include "gi2d/hrc/direct_light.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include "gi2d/hrc/compact_lights.h"
#include "luxel/core/memory.h"
#include "luxel/core/parallel.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/ray_march.h"

namespace luxel::gi2d::hrc {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// atan2 in [0, 2 pi) to 2e-6 rad (a minimax polynomial on [0, 1]): the fans' rays are at
// least 1 / 400 rad apart, and std::atan2 was a tenth of the gather.
inline double angleOf(double y, double x) {
    const double ax = std::abs(x), ay = std::abs(y);
    const double lo = std::min(ax, ay), hi = std::max(ax, ay);
    if (!(hi > 0)) return 0.0;
    const double a = lo / hi, s = a * a;
    double r =
        ((((-0.0117212 * s + 0.05265332) * s - 0.11643287) * s + 0.19354346) * s - 0.33262347) * s +
        0.99997726;
    r *= a;
    if (ay > ax) r = std::numbers::pi / 2 - r;
    if (x < 0) r = std::numbers::pi - r;
    if (y < 0) r = kTwoPi - r;
    return r >= kTwoPi ? 0.0 : r;
}

// The light's own pixels, a byte per pixel of its bounding box: fan rays cross them freely (their
// absorption is in the intensity table).
struct OwnPixels {
    int x0, y0, w, h;
    std::vector<std::uint8_t> bits;
    OwnPixels(const CompactLight& light, int width)
        : x0(light.x0),
          y0(light.y0),
          w(light.x1 - light.x0 + 1),
          h(light.y1 - light.y0 + 1),
          bits(static_cast<std::size_t>(w) * h, 0) {
        for (std::uint32_t i : light.pixels) {
            const int x = static_cast<int>(i % width) - x0, y = static_cast<int>(i / width) - y0;
            bits[static_cast<std::size_t>(y) * w + x] = 1;
        }
    }
    bool has(int x, int y) const {
        x -= x0, y -= y0;
        return x >= 0 && y >= 0 && x < w && y < h && bits[static_cast<std::size_t>(y) * w + x];
    }
};

// Counts of absorbing pixels (sigma > 0 in some channel, as the fan rays see them: the light's
// own pixels left out) over any box in O(1): a summed-area table of the canvas, less one of the
// light's bounding box. A fan sector whose wedge holds none has T = 1 everywhere in it, which its
// two bounding rays already read exactly (§12.5, vacuum sectors).
class Absorbers {
  public:
    explicit Absorbers(const Medium2D& medium)
        : w_(medium.width()),
          h_(medium.height()),
          canvas_(static_cast<std::size_t>(w_ + 1) * (h_ + 1), 0) {
        for (int y = 0; y < h_; ++y) {
            std::uint32_t row = 0;
            for (int x = 0; x < w_; ++x) {
                row += absorbing(medium.absorption.rgb(x, y)) ? 1u : 0u;
                canvas_[index(x + 1, y + 1, w_)] = canvas_[index(x + 1, y, w_)] + row;
            }
        }
    }
    static bool absorbing(const Rgb& s) { return s.r > 0 || s.g > 0 || s.b > 0; }
    // The light's own absorbing pixels, subtracted from every count.
    void setOwn(const Medium2D& medium, const OwnPixels& own) {
        own_ = &own;
        ownCounts_.assign(static_cast<std::size_t>(own.w + 1) * (own.h + 1), 0);
        for (int y = 0; y < own.h; ++y) {
            std::uint32_t row = 0;
            for (int x = 0; x < own.w; ++x) {
                row += own.has(own.x0 + x, own.y0 + y) &&
                               absorbing(medium.absorption.rgb(own.x0 + x, own.y0 + y))
                           ? 1u
                           : 0u;
                ownCounts_[index(x + 1, y + 1, own.w)] = ownCounts_[index(x + 1, y, own.w)] + row;
            }
        }
    }
    // Absorbing pixels in [x0, x1] x [y0, y1] (inclusive, clamped to the canvas), own ones out.
    std::uint32_t count(int x0, int y0, int x1, int y1) const {
        x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, w_ - 1),
        y1 = std::min(y1, h_ - 1);
        if (x0 > x1 || y0 > y1) return 0;
        std::uint32_t n = sum(canvas_, w_, x0, y0, x1, y1);
        if (own_ != nullptr) {
            const int ox0 = std::max(x0, own_->x0) - own_->x0,
                      oy0 = std::max(y0, own_->y0) - own_->y0;
            const int ox1 = std::min(x1, own_->x0 + own_->w - 1) - own_->x0,
                      oy1 = std::min(y1, own_->y0 + own_->h - 1) - own_->y0;
            if (ox0 <= ox1 && oy0 <= oy1) n -= sum(ownCounts_, own_->w, ox0, oy0, ox1, oy1);
        }
        return n;
    }
    // Whether the wedge from o between angles a0 < a1 holds no absorbing pixel on the canvas:
    // boxes around its pieces, each as long as the wedge is wide there (2 px at least).
    bool vacuumWedge(Vec2d o, double a0, double a1) const {
        const double c0 = std::cos(a0), s0 = std::sin(a0), c1 = std::cos(a1), s1 = std::sin(a1);
        const double far = std::hypot(std::max(o.x, w_ - o.x), std::max(o.y, h_ - o.y)) + 1.0;
        // The arc bulges past the chord by r (a1 - a0)^2 / 8: under the pad for any canvas here.
        constexpr double pad = 0.5;
        for (double r = 0.0; r < far;) {
            const double next = r + std::max(2.0, r * (a1 - a0));
            const double xs[4] = {o.x + r * c0, o.x + r * c1, o.x + next * c0, o.x + next * c1};
            const double ys[4] = {o.y + r * s0, o.y + r * s1, o.y + next * s0, o.y + next * s1};
            const auto [xl, xh] = std::minmax_element(xs, xs + 4);
            const auto [yl, yh] = std::minmax_element(ys, ys + 4);
            if (count(static_cast<int>(std::floor(*xl - pad)),
                      static_cast<int>(std::floor(*yl - pad)),
                      static_cast<int>(std::floor(*xh + pad)),
                      static_cast<int>(std::floor(*yh + pad))) > 0)
                return false;
            r = next;
        }
        return true;
    }

  private:
    static std::size_t index(int x, int y, int w) {
        return static_cast<std::size_t>(y) * (w + 1) + x;
    }
    static std::uint32_t sum(const std::vector<std::uint32_t>& t, int w, int x0, int y0, int x1,
                             int y1) {
        return t[index(x1 + 1, y1 + 1, w)] - t[index(x0, y1 + 1, w)] - t[index(x1 + 1, y0, w)] +
               t[index(x0, y0, w)];
    }
    int w_, h_;
    std::vector<std::uint32_t> canvas_, ownCounts_;
    const OwnPixels* own_ = nullptr;
};

// One ray of a fan: the transmittance from the source at 0, 1, 2, ... px (RGB); beyond the last
// sample it is 0 if the ray faded and the last sample's if it left the canvas, which one more
// sample at the end holds.
struct FanRay {
    std::vector<float> t;  // (samples + 1) x RGB
    int n = 0;             // samples
    bool open = false;
    int xLo = std::numeric_limits<int>::max(), xHi = -1, yLo = std::numeric_limits<int>::max(),
        yHi = -1;
    int samples() const { return n; }
    bool dark(int i) const { return !open && i >= n; }
    // Left the canvas with nothing absorbed on the way: T = 1 all along, no samples stored.
    bool clear = false;
    const float* at(int i) const {
        static constexpr float kOnes[3] = {1, 1, 1};
        return clear ? kOnes : t.data() + static_cast<std::size_t>(std::min(i, n)) * 3;
    }
};

FanRay marchFanRay(const Medium2D& medium, const OwnPixels& own, Vec2d origin, double angle) {
    const int w = medium.width(), h = medium.height();
    const double dx = std::cos(angle), dy = std::sin(angle);
    const double inf = std::numeric_limits<double>::infinity();
    int cx = std::clamp(static_cast<int>(std::floor(origin.x)), 0, w - 1);
    int cy = std::clamp(static_cast<int>(std::floor(origin.y)), 0, h - 1);
    const int stepX = dx > 0 ? 1 : -1, stepY = dy > 0 ? 1 : -1;
    double tMaxX = dx > 0 ? (cx + 1 - origin.x) / dx : dx < 0 ? (cx - origin.x) / dx : inf;
    double tMaxY = dy > 0 ? (cy + 1 - origin.y) / dy : dy < 0 ? (cy - origin.y) / dy : inf;
    const double tDeltaX = dx != 0 ? std::abs(1.0 / dx) : inf;
    const double tDeltaY = dy != 0 ? std::abs(1.0 / dy) : inf;
    FanRay ray;
    float T[3] = {1, 1, 1};
    // Samples go to a per-thread scratch first: one allocation of the right size per ray.
    thread_local std::vector<float> samples;
    samples.clear();
    for (float v : T) samples.push_back(v);
    double t = 0.0;
    int next = 1;
    while (true) {
        ray.xLo = std::min(ray.xLo, cx), ray.xHi = std::max(ray.xHi, cx);
        ray.yLo = std::min(ray.yLo, cy), ray.yHi = std::max(ray.yHi, cy);
        const double exit = std::min(tMaxX, tMaxY);
        const Rgb s = own.has(cx, cy) ? Rgb{} : medium.absorption.rgb(cx, cy);
        const float sigma[3] = {s.r, s.g, s.b};
        if (s.r > 0 && s.r == s.g && s.g == s.b) {
            // Grey (fog, walls): one exp for the three channels, the same values.
            for (; next <= exit; ++next) {
                const float e = std::exp(-sigma[0] * static_cast<float>(next - t));
                for (float v : T) samples.push_back(v * e);
            }
            const float e = std::exp(-sigma[0] * static_cast<float>(exit - t));
            for (float& v : T) v *= e;
        } else {
            for (; next <= exit; ++next) {
                for (int c = 0; c < 3; ++c) {
                    samples.push_back(
                        sigma[c] > 0 ? T[c] * std::exp(-sigma[c] * static_cast<float>(next - t))
                                     : T[c]);
                }
            }
            for (int c = 0; c < 3; ++c) {
                if (sigma[c] > 0) T[c] *= std::exp(-sigma[c] * static_cast<float>(exit - t));
            }
        }
        t = exit;
        if (std::max(T[0], std::max(T[1], T[2])) < kDirectCutoff) break;
        if (tMaxX < tMaxY) {
            cx += stepX, tMaxX += tDeltaX;
        } else {
            cy += stepY, tMaxY += tDeltaY;
        }
        if (cx < 0 || cy < 0 || cx >= w || cy >= h) {
            ray.open = true;
            break;
        }
    }
    ray.n = static_cast<int>(samples.size() / 3);
    ray.clear = ray.open && T[0] == 1 && T[1] == 1 && T[2] == 1;
    if (ray.clear) return ray;
    for (int c = 0; c < 3; ++c) samples.push_back(ray.open ? samples[samples.size() - 3] : 0.0f);
    ray.t.assign(samples.begin(), samples.end());
    return ray;
}

// A point source's fan: the rays, the sectors they split into and the pixels they reach.
struct Fan {
    std::vector<FanRay> rays;
    std::vector<int> first, count;  // sector i: rays first[i] .. first[i] + count[i] - 1
    int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
    std::uint64_t steps = 0;
    // No ray left the canvas: every ray is dark from `reach` px on (its longest ray's samples).
    bool closed = true;
    int reach = 0;
};

// The fan starts with kFanSectors rays and splits each sector
// between two of them into as many rays as the longer of the two is long in px of arc there
// (a sector the source does not shine into keeps its two rays). With `absorbers`, a sector
// whose wedge holds no absorbing pixel keeps its two rays too: T = 1 all over it.
Fan marchFan(const Medium2D& medium, const OwnPixels& own, const PointSource& source,
             const Absorbers* absorbers) {
    const int w = medium.width(), h = medium.height();
    const Vec2d o = source.position;
    constexpr int sectors = kFanSectors;
    constexpr double sectorAngle = kTwoPi / sectors;
    auto dark = [&](double from, double to) {  // no light between these angles
        const int n = static_cast<int>(source.intensity.size());
        const double perEntry = kTwoPi / n;
        for (int m = static_cast<int>(std::floor(from / perEntry - 0.5)) - 1;
             m <= static_cast<int>(std::ceil(to / perEntry - 0.5)) + 1; ++m) {
            const Rgb& e = source.intensity[static_cast<std::size_t>(((m % n) + n) % n)];
            if (e.r > 0 || e.g > 0 || e.b > 0) return false;
        }
        return true;
    };
    std::vector<FanRay> coarse(sectors);
    std::vector<std::uint8_t> lit(sectors);
    for (int i = 0; i < sectors; ++i) {
        lit[static_cast<std::size_t>(i)] = !dark(i * sectorAngle, (i + 1) * sectorAngle);
    }
    parallelForRange(sectors, 8, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            if (lit[static_cast<std::size_t>(i)] ||
                lit[static_cast<std::size_t>((i + sectors - 1) % sectors)])
                coarse[static_cast<std::size_t>(i)] = marchFanRay(medium, own, o, i * sectorAngle);
        }
    });
    // Sector i holds rays first[i] .. first[i] + count[i] - 1, the first the coarse ray i.
    std::vector<std::uint8_t> vacuum(sectors, 0);
    if (absorbers != nullptr) {
        parallelForRange(sectors, 8, [&](int begin, int end) {
            for (int i = begin; i < end; ++i) {
                const auto si = static_cast<std::size_t>(i);
                vacuum[si] = lit[si] && coarse[si].clear &&
                             coarse[static_cast<std::size_t>((i + 1) % sectors)].clear &&
                             absorbers->vacuumWedge(o, i * sectorAngle, (i + 1) * sectorAngle);
            }
        });
    }
    Fan result;
    std::vector<int>& first = result.first;
    std::vector<int>& count = result.count;
    first.assign(sectors + 1, 0);
    count.assign(sectors, 0);
    for (int i = 0; i < sectors; ++i) {
        const auto si = static_cast<std::size_t>(i);
        const int longest = std::max(coarse[si].samples(),
                                     coarse[static_cast<std::size_t>((i + 1) % sectors)].samples());
        count[si] =
            lit[si] && !vacuum[si]
                ? std::max(1, static_cast<int>(std::ceil(sectorAngle * longest * kFanRaysPerPx)))
                : 1;
        first[si + 1] = first[si] + count[si];
    }
    std::vector<FanRay>& fan = result.rays;
    fan.resize(static_cast<std::size_t>(first[sectors]));
    parallelForRange(sectors, 1, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const auto si = static_cast<std::size_t>(i);
            fan[static_cast<std::size_t>(first[si])] = std::move(coarse[si]);
            for (int m = 1; m < count[si]; ++m) {
                fan[static_cast<std::size_t>(first[si] + m)] = marchFanRay(
                    medium, own, o, (i + static_cast<double>(m) / count[si]) * sectorAngle);
            }
        }
    });
    result.x0 = w, result.y0 = h;
    for (const FanRay& r : fan) {
        result.steps += static_cast<std::uint64_t>(r.samples());
        result.closed = result.closed && !r.open;
        result.reach = std::max(result.reach, r.samples());
        if (r.samples() == 0) continue;
        result.x0 = std::min(result.x0, r.xLo), result.x1 = std::max(result.x1, r.xHi);
        result.y0 = std::min(result.y0, r.yLo), result.y1 = std::max(result.y1, r.yHi);
    }
    return result;
}

// Adds share x the source's light to `out` at every pixel its fan reaches that is not within
// nearRadius of the light's centre.
void gatherFan(const CompactLight& light, const PointSource& source, const Fan& fan_,
               double nearRadius, float share, Image& out) {
    constexpr int sectors = kFanSectors;
    constexpr double sectorAngle = kTwoPi / sectors;
    const Vec2d o = source.position;
    const std::vector<FanRay>& fan = fan_.rays;
    const std::vector<int>& first = fan_.first;
    const std::vector<int>& count = fan_.count;
    const int x0 = fan_.x0, x1 = fan_.x1, y0 = fan_.y0, y1 = fan_.y1;
    if (x1 < x0) return;
    parallelForRange(y1 - y0 + 1, 4, [&](int begin, int end) {
        for (int y = y0 + begin; y < y0 + end; ++y) {
            // A closed fan lights nothing from `reach` px on (both rays dark there): the row's
            // pixels within it, a pixel of margin (what fades in fog, the corners of its box).
            int xa = x0, xb = x1;
            if (fan_.closed) {
                const double dy = y + 0.5 - o.y, r = fan_.reach + 1.0;
                if (dy * dy >= r * r) continue;
                const double half = std::sqrt(r * r - dy * dy);
                xa = std::max(x0, static_cast<int>(std::floor(o.x - half - 0.5)));
                xb = std::min(x1, static_cast<int>(std::ceil(o.x + half - 0.5)));
            }
            for (int x = xa; x <= xb; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                const double cx = px - light.centre.x, cy = py - light.centre.y;
                if (cx * cx + cy * cy < nearRadius * nearRadius) continue;
                const double vx = px - o.x, vy = py - o.y;
                const double angle = angleOf(vy, vx);
                const double d = std::sqrt(vx * vx + vy * vy);
                const double fs = angle / sectorAngle;
                const int i = std::min(static_cast<int>(fs), sectors - 1);
                const double fm = (fs - i) * count[static_cast<std::size_t>(i)];
                const int m =
                    std::min(static_cast<int>(fm), count[static_cast<std::size_t>(i)] - 1);
                const float a = static_cast<float>(fm - m);
                const int j0 = first[static_cast<std::size_t>(i)] + m;
                const int j1 = m + 1 < count[static_cast<std::size_t>(i)]
                                   ? j0 + 1
                                   : first[static_cast<std::size_t>((i + 1) % sectors)];
                const int k = static_cast<int>(d);
                const float g = static_cast<float>(d - k);
                const FanRay& r0 = fan[static_cast<std::size_t>(j0)];
                const FanRay& r1 = fan[static_cast<std::size_t>(j1)];
                if (r0.dark(k) && r1.dark(k)) continue;  // behind what stopped both rays
                const Rgb intensity = source.intensityTowards(angle);
                if (!(intensity.r > 0 || intensity.g > 0 || intensity.b > 0)) continue;
                const float e[3] = {intensity.r, intensity.g, intensity.b};
                const float scale = share * static_cast<float>(1.0 / (kTwoPi * d));
                float* dst = &out.at(x, y, 0);
                if (r0.clear && r1.clear) {  // T = 1
                    for (int c = 0; c < 3; ++c) dst[c] += e[c] * scale;
                    continue;
                }
                const float *a0 = r0.at(k), *b0 = r0.at(k + 1), *a1 = r1.at(k), *b1 = r1.at(k + 1);
                for (int c = 0; c < 3; ++c) {
                    const float t0 = a0[c] + g * (b0[c] - a0[c]);
                    const float t1 = a1[c] + g * (b1[c] - a1[c]);
                    dst[c] += e[c] * scale * (t0 + a * (t1 - t0));
                }
            }
        }
    });
}

// The pixels within nearRadius of the light's centre: the mean radiance over the light's cone,
// its emission alone, marched exactly through a window of the medium around it.
void addNear(const Medium2D& medium, const CompactLight& light, double nearRadius, float share,
             Image& out) {
    const int w = medium.width(), h = medium.height();
    const int pad = static_cast<int>(std::ceil(nearRadius + light.radius)) + 1;
    const int wx0 = std::max(0, light.x0 - pad), wy0 = std::max(0, light.y0 - pad);
    const int wx1 = std::min(w - 1, light.x1 + pad), wy1 = std::min(h - 1, light.y1 + pad);
    const int ww = wx1 - wx0 + 1, wh = wy1 - wy0 + 1;
    Medium2D local{Image(ww, wh, 3), Image(ww, wh, 3), Rgb{}};
    for (int y = 0; y < wh; ++y) {
        for (int x = 0; x < ww; ++x) {
            local.absorption.setRgb(x, y, medium.absorption.rgb(wx0 + x, wy0 + y));
        }
    }
    for (std::uint32_t i : light.pixels) {
        const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
        local.emission.setRgb(x - wx0, y - wy0, medium.emission.rgb(x, y));
    }
    const RayMarcher marcher(local);
    std::vector<std::uint32_t> pixels;
    for (int y = wy0; y <= wy1; ++y) {
        for (int x = wx0; x <= wx1; ++x) {
            if (std::hypot(x + 0.5 - light.centre.x, y + 0.5 - light.centre.y) < nearRadius)
                pixels.push_back(static_cast<std::uint32_t>(y * w + x));
        }
    }
    parallelForRange(static_cast<int>(pixels.size()), 8, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const int x = static_cast<int>(pixels[static_cast<std::size_t>(k)] % w);
            const int y = static_cast<int>(pixels[static_cast<std::size_t>(k)] / w);
            const Vec2d p{x + 0.5 - wx0, y + 0.5 - wy0};
            const double vx = light.centre.x - (x + 0.5), vy = light.centre.y - (y + 0.5);
            const double d = std::hypot(vx, vy);
            const double half = d > light.radius ? std::asin(light.radius / d) : std::numbers::pi;
            const double towards = std::atan2(vy, vx);
            double sum[3] = {0, 0, 0};
            for (int m = 0; m < kDirectNearRays; ++m) {
                const double angle = towards - half + 2.0 * half * (m + 0.5) / kDirectNearRays;
                const RaySegment s = marcher.march(p, {std::cos(angle), std::sin(angle)},
                                                   d + light.radius + 1.0, 1e-6f);
                sum[0] += s.radiance.r, sum[1] += s.radiance.g, sum[2] += s.radiance.b;
            }
            const double weight = share * 2.0 * half / kDirectNearRays / kTwoPi;
            for (int c = 0; c < 3; ++c) out.at(x, y, c) += static_cast<float>(sum[c] * weight);
        }
    });
}

}  // namespace

DirectLight exactDirectLight(const Medium2D& medium, const DirectLightOptions& options) {
    LightScores scores = LightScores::of(medium, true);
    return exactDirectLight(medium, scores, options);
}

DirectLight exactDirectLight(const Medium2D& medium, LightScores& scores,
                             const DirectLightOptions& options) {
    DirectLight direct;
    const int w = medium.width(), h = medium.height();
    std::vector<CompactLight> lights = findCompactLights(medium, scores);
    if (lights.empty()) return direct;
    const double pixels = static_cast<double>(w) * h;
    const double budget = kDirectWorkPerPixel * std::max(pixels, kDirectBudgetFloorPixels);
    std::optional<Absorbers> absorbers;
    if (options.vacuumSectors) absorbers.emplace(medium);
    for (CompactLight& light : lights) {
        // Brightest first while the budget lasts; a light over it stays with the cascades. Its
        // work: the near gather's rays at their longest, then each fan's samples and the pixels
        // its gather visits, counted as the fans are marched (at most one light's fans wasted).
        const double nearRadius = kDirectNearFactor * light.radius + kDirectNearMargin;
        double work = std::numbers::pi * nearRadius * nearRadius * kDirectNearRays *
                      (nearRadius + light.radius + 1.0);
        if (static_cast<double>(direct.work) + work > budget) break;
        makePointSources(medium, light);
        const OwnPixels own(light, w);
        if (absorbers) absorbers->setOwn(medium, own);
        std::vector<Fan> fans;
        for (const PointSource& source : light.sources) {
            fans.push_back(marchFan(medium, own, source, absorbers ? &*absorbers : nullptr));
            const Fan& f = fans.back();
            work +=
                static_cast<double>(f.steps) +
                static_cast<double>(std::max(0, f.x1 - f.x0 + 1)) * std::max(0, f.y1 - f.y0 + 1);
            if (static_cast<double>(direct.work) + work > budget) break;
        }
        if (static_cast<double>(direct.work) + work > budget) break;
        if (direct.fluence.empty()) direct.fluence = Image(w, h, 3);
        const auto share = static_cast<float>(light.share);
        addNear(medium, light, nearRadius, share, direct.fluence);
        for (std::size_t k = 0; k < fans.size(); ++k) {
            gatherFan(light, light.sources[k], fans[k], nearRadius, share, direct.fluence);
        }
        direct.work += static_cast<std::uint64_t>(work);
        for (std::uint32_t i : light.pixels) direct.removed.emplace_back(i, share);
    }
    std::sort(direct.removed.begin(), direct.removed.end());
    return direct;
}

Status checkDirectLightMemory(int width, int height) {
    return checkMemory(
        mediumBytes(width, height) + estimateHrcMemory(width, height).output +
            LightScores::bytesFor(width, height, true),
        "HRC's direct light at " + std::to_string(width) + "x" + std::to_string(height));
}

Medium2D withoutDirectLights(const Medium2D& medium, const DirectLight& direct) {
    Medium2D reduced = medium;
    const int w = medium.width();
    for (const auto& [i, share] : direct.removed) {
        const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
        for (int c = 0; c < 3; ++c) reduced.emission.at(x, y, c) *= 1.0f - share;
    }
    return reduced;
}

void addDirectLight(const DirectLight& direct, Image& fluence) {
    if (direct.empty()) return;
    float* out = fluence.data();
    const float* add = direct.fluence.data();
    for (std::size_t i = 0; i < fluence.size(); ++i) out[i] += add[i];
}

std::optional<Result<Image>> solveSplittingDirectLight(
    const Medium2D& medium, LightScores& scores, const HrcOptions& options,
    const std::function<Result<Image>(const Medium2D&, LightScores&, const HrcOptions&)>& solveRest,
    const std::function<void(const DirectLightSplit&)>& onSplit) {
    if (Status s = checkDirectLightMemory(medium.width(), medium.height()); !s) {
        return Result<Image>(s.error());
    }
    const auto start = std::chrono::steady_clock::now();
    const DirectLight direct = exactDirectLight(medium, scores);
    if (direct.empty()) return std::nullopt;
    onSplit({std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                 .count(),
             direct.work});
    HrcOptions rest = options;
    rest.exactDirectLight = false;
    const Medium2D reduced = withoutDirectLights(medium, direct);
    // The removed pixels' rows, ascending with them, scored again run by run.
    const int w = medium.width();
    for (std::size_t k = 0; k < direct.removed.size();) {
        const int y0 = static_cast<int>(direct.removed[k].first / w);
        int y1 = y0 + 1;
        while (k < direct.removed.size() && static_cast<int>(direct.removed[k].first / w) <= y1) {
            y1 = static_cast<int>(direct.removed[k].first / w) + 1;
            ++k;
        }
        scores.rescoreRows(reduced, y0, y1);
    }
    Result<Image> solved = solveRest(reduced, scores, rest);
    if (solved) addDirectLight(direct, *solved);
    return solved;
}

}  // namespace luxel::gi2d::hrc
