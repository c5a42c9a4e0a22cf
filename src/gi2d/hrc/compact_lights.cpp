// Finding the compact lights and tabulating their point sources' intensity (§12.5).
#include "gi2d/hrc/compact_lights.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <utility>

#include "gi2d/hrc/emitting_pixels.h"
#include "gi2d/hrc/light_scores.h"
#include "luxel/core/parallel.h"

namespace luxel::gi2d::hrc {

namespace {

// What a pixel sends out across one pixel length, max over channels: E (1 - exp(-sigma)).
float emitted(const Medium2D& medium, int x, int y) {
    const Rgb e = medium.emission.rgb(x, y), s = medium.absorption.rgb(x, y);
    float most = 0.0f;
    const float es[3] = {e.r, e.g, e.b}, ss[3] = {s.r, s.g, s.b};
    for (int c = 0; c < 3; ++c) {
        const float v = es[c] * (1.0f - std::exp(-ss[c]));
        if (v > most) most = v;  // NaN stays out
    }
    return most;
}

// emitted(medium, x, y) > 0, without its exponentials where no channel's emission and absorption
// have one sign (a product that is not positive then), as in most pixels of a canvas.
bool emits(const Medium2D& medium, int x, int y) {
    const Rgb e = medium.emission.rgb(x, y), s = medium.absorption.rgb(x, y);
    const auto sameSign = [](float a, float b) { return (a > 0 && b > 0) || (a < 0 && b < 0); };
    if (!sameSign(e.r, s.r) && !sameSign(e.g, s.g) && !sameSign(e.b, s.b)) return false;
    return emitted(medium, x, y) > 0.0f;
}

// Pixels [x0, x1] of row y, labelled.
struct Span {
    int y, x0, x1;
};

// Labels every emitting pixel 8-connected to the spans (labelled already), a maximal span of
// emitting pixels at a time: the rest of a group found too large to be a compact light, where
// the order of its pixels no longer matters. Each pixel is labelled once and each span's three
// rows scanned once, which is much less than a pixel's eight neighbours each.
void labelConnected(std::uint8_t* state, int w, int h, std::vector<Span>& spans) {
    while (!spans.empty()) {
        const Span s = spans.back();
        spans.pop_back();
        for (int ny = std::max(0, s.y - 1); ny <= std::min(h - 1, s.y + 1); ++ny) {
            std::uint8_t* const row = state + static_cast<std::size_t>(ny) * w;
            for (int x = std::max(0, s.x0 - 1); x <= std::min(w - 1, s.x1 + 1); ++x) {
                if (row[x] != 1) continue;
                int a = x, b = x;
                while (a > 0 && row[a - 1] == 1) --a;
                while (b + 1 < w && row[b + 1] == 1) ++b;
                std::fill(row + a, row + b + 1, std::uint8_t{2});
                spans.push_back({ny, a, b});
                x = b;
            }
        }
    }
}

}  // namespace

std::vector<CompactLight> findCompactLights(const Medium2D& medium) {
    LightScores scores = LightScores::of(medium, true);
    return findCompactLights(medium, scores);
}

std::vector<CompactLight> findCompactLights(const Medium2D& medium, LightScores& scores) {
    const int w = medium.width(), h = medium.height();
    const std::size_t count = static_cast<std::size_t>(w) * h;
    std::vector<CompactLight> lights;
    if (count == 0) return lights;
    const float brightest = scores.brightest();
    if (!(brightest > 0.0f)) return lights;
    const float threshold = lightScoreThreshold(brightest);
    // The emitting pixels, by rows on every thread: every solve of a canvas with lights pays this
    // pass, most of them finding no compact light (a room's walls). Vectors tell the sure ones
    // and the ones that surely do not (with the scores, where they came with them); the
    // exponentials the few others.
    // 0: no emission, 1: emitting and not yet labelled, 2: labelled.
    std::unique_ptr<std::uint8_t[]> state = scores.takeEmitting();
    const bool coded = state != nullptr;
    // Not zeroed first: the rows' passes write every byte, each row's pages on its thread.
    if (!coded) state = std::make_unique_for_overwrite<std::uint8_t[]>(count);
    parallelForRange(h, 16, [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
            const std::size_t row = static_cast<std::size_t>(y) * w;
            std::uint8_t* const out = state.get() + row;
            const bool unsure = coded ? std::memchr(out, 2, static_cast<std::size_t>(w)) != nullptr
                                      : emittingRow(medium.emission.data() + row * 3,
                                                    medium.absorption.data() + row * 3, w, out) > 0;
            if (!unsure) continue;
            for (int x = 0; x < w; ++x) {
                if (out[x] == 2) out[x] = emits(medium, x, y) ? 1 : 0;
            }
        }
    });

    std::vector<std::uint32_t> stack;
    std::vector<Span> spans;
    for (std::size_t seed = 0; seed < count; ++seed) {
        // The next emitting pixel not yet labelled, the least index of its group.
        const void* next = std::memchr(state.get() + seed, 1, count - seed);
        if (next == nullptr) break;
        seed = static_cast<std::size_t>(static_cast<const std::uint8_t*>(next) - state.get());
        CompactLight light;
        light.x0 = light.x1 = static_cast<int>(seed % w);
        light.y0 = light.y1 = static_cast<int>(seed / w);
        bool small = true;
        state[seed] = 2;
        stack.assign(1, static_cast<std::uint32_t>(seed));
        while (!stack.empty()) {
            const std::uint32_t i = stack.back();
            stack.pop_back();
            const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
            light.x0 = std::min(light.x0, x), light.x1 = std::max(light.x1, x);
            light.y0 = std::min(light.y0, y), light.y1 = std::max(light.y1, y);
            small = small && light.x1 - light.x0 < kCompactLightMaxSize &&
                    light.y1 - light.y0 < kCompactLightMaxSize;
            if (!small) {
                // Too large: the rest of the group labelled by spans, from this pixel and the
                // labelled ones whose neighbours are not yet looked at.
                spans.assign(1, {y, x, x});
                for (const std::uint32_t j : stack) {
                    spans.push_back({static_cast<int>(j / w), static_cast<int>(j % w),
                                     static_cast<int>(j % w)});
                }
                stack.clear();
                labelConnected(state.get(), w, h, spans);
                break;
            }
            light.pixels.push_back(i);
            light.score = std::max(light.score, scores.at(i));
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const std::size_t j = static_cast<std::size_t>(ny) * w + nx;
                    if (state[j] != 1) continue;
                    state[j] = 2;
                    stack.push_back(static_cast<std::uint32_t>(j));
                }
            }
        }
        if (!small || !(light.score >= threshold)) continue;
        double weight = 0, mx = 0, my = 0, mxx = 0;
        for (std::uint32_t i : light.pixels) {
            const double x = i % w + 0.5, y = i / w + 0.5;
            const double e = emitted(medium, static_cast<int>(i % w), static_cast<int>(i / w));
            weight += e, mx += e * x, my += e * y, mxx += e * (x * x + y * y);
        }
        mx /= weight, my /= weight;
        const double rms = std::sqrt(std::max(0.0, mxx / weight - mx * mx - my * my));
        light.rmsRadius = rms;
        light.share = std::clamp(
            (kCompactNoneRadius - rms) / (kCompactNoneRadius - kCompactFullRadius), 0.0, 1.0);
        if (!(light.share > 0)) continue;
        std::sort(light.pixels.begin(), light.pixels.end());
        light.centre = {(light.x0 + light.x1 + 1) * 0.5, (light.y0 + light.y1 + 1) * 0.5};
        const double hx = (light.x1 - light.x0 + 1) * 0.5, hy = (light.y1 - light.y0 + 1) * 0.5;
        light.radius = std::hypot(hx, hy);
        lights.push_back(std::move(light));
    }
    std::stable_sort(
        lights.begin(), lights.end(),
        [](const CompactLight& a, const CompactLight& b) { return a.score > b.score; });
    return lights;
}

namespace {

// One line of the intensity table through the light's window (vacuum outside its pixels), from
// the viewer's side: each pixel's E (1 - t) times the transmittance in front of it goes to its
// source (Amanatides-Woo over the window's cells).
void marchAttributing(const std::vector<float>& sigma, const std::vector<float>& emission,
                      const std::vector<int>& sourceOf, int ww, int wh, Vec2d origin, Vec2d dir,
                      double length, std::vector<double>& sums) {
    const double inf = std::numeric_limits<double>::infinity();
    // Clip to the window.
    double t0 = 0.0, t1 = length;
    const double o[2] = {origin.x, origin.y}, d[2] = {dir.x, dir.y},
                 hi[2] = {double(ww), double(wh)};
    for (int a = 0; a < 2; ++a) {
        if (d[a] == 0.0) {
            if (o[a] < 0 || o[a] > hi[a]) return;
            continue;
        }
        double ta = (0 - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    }
    if (t0 >= t1) return;
    const Vec2d p = origin + dir * ((t0 + t1) * 0.5 - (t1 - t0) * 0.5);
    int cx = std::clamp(static_cast<int>(std::floor(p.x + dir.x * 1e-9)), 0, ww - 1);
    int cy = std::clamp(static_cast<int>(std::floor(p.y + dir.y * 1e-9)), 0, wh - 1);
    const int stepX = dir.x > 0 ? 1 : -1, stepY = dir.y > 0 ? 1 : -1;
    double tMaxX = dir.x > 0   ? (cx + 1 - origin.x) / dir.x
                   : dir.x < 0 ? (cx - origin.x) / dir.x
                               : inf;
    double tMaxY = dir.y > 0   ? (cy + 1 - origin.y) / dir.y
                   : dir.y < 0 ? (cy - origin.y) / dir.y
                               : inf;
    const double dX = dir.x != 0 ? std::abs(1.0 / dir.x) : inf,
                 dY = dir.y != 0 ? std::abs(1.0 / dir.y) : inf;
    double t = t0, T[3] = {1, 1, 1};
    while (t < t1) {
        const double exit = std::min(std::min(tMaxX, tMaxY), t1);
        const std::size_t i = static_cast<std::size_t>(cy) * ww + cx;
        const int source = sourceOf[i];
        if (source >= 0 && exit > t) {
            const float* sc = &sigma[i * 3];
            const bool grey = sc[0] == sc[1] && sc[1] == sc[2];  // one exp for all channels
            const double greyT = std::exp(-static_cast<double>(sc[0]) * (exit - t));
            for (int c = 0; c < 3; ++c) {
                const double tc = grey ? greyT : std::exp(-static_cast<double>(sc[c]) * (exit - t));
                sums[static_cast<std::size_t>(source) * 3 + c] +=
                    T[c] * emission[i * 3 + c] * (1 - tc);
                T[c] *= tc;
            }
        }
        t = exit;
        if (tMaxX < tMaxY) {
            cx += stepX, tMaxX += dX;
        } else {
            cy += stepY, tMaxY += dY;
        }
        if (cx < 0 || cy < 0 || cx >= ww || cy >= wh) break;
    }
}

}  // namespace

void makePointSources(const Medium2D& medium, CompactLight& light) {
    const int w = medium.width();
    // A window of the light's bounding box and one pixel around, vacuum but for its pixels.
    const int wx0 = light.x0 - 1, wy0 = light.y0 - 1;
    const int ww = light.x1 - light.x0 + 3, wh = light.y1 - light.y0 + 3;
    const std::size_t cells = static_cast<std::size_t>(ww) * wh;
    std::vector<float> sigma(cells * 3, 0.0f), emission(cells * 3, 0.0f);
    std::vector<int> sourceOf(cells, -1);
    // Blocks on the canvas's grid, not the light's: as a light moves, its sources' centres move
    // with the emission instead of regrouping when its bounding box grows.
    std::map<std::pair<int, int>, int> blocks;
    std::vector<double> weight, cx, cy;
    for (std::uint32_t i : light.pixels) {
        const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
        const std::size_t j = static_cast<std::size_t>(y - wy0) * ww + (x - wx0);
        const Rgb s = medium.absorption.rgb(x, y), e = medium.emission.rgb(x, y);
        sigma[j * 3] = s.r, sigma[j * 3 + 1] = s.g, sigma[j * 3 + 2] = s.b;
        emission[j * 3] = e.r, emission[j * 3 + 1] = e.g, emission[j * 3 + 2] = e.b;
        const auto [it, added] = blocks.try_emplace({x / kSourceBlock, y / kSourceBlock},
                                                    static_cast<int>(weight.size()));
        if (added) weight.push_back(0), cx.push_back(0), cy.push_back(0);
        const auto k = static_cast<std::size_t>(it->second);
        sourceOf[j] = it->second;
        const double e1 = emitted(medium, x, y);
        weight[k] += e1, cx[k] += e1 * (x + 0.5), cy[k] += e1 * (y + 0.5);
    }
    const std::size_t sources = weight.size();
    const Vec2d middle{ww * 0.5, wh * 0.5};
    const double reach = std::hypot(ww, wh) * 0.5 + 1.0;
    std::vector<std::vector<Rgb>> tables(sources, std::vector<Rgb>(kIntensityDirections));
    std::vector<double> sums(sources * 3);
    for (int m = 0; m < kIntensityDirections; ++m) {
        const double angle = 2.0 * std::numbers::pi * (m + 0.5) / kIntensityDirections;
        const Vec2d u{std::cos(angle), std::sin(angle)}, n{-u.y, u.x};
        std::fill(sums.begin(), sums.end(), 0.0);
        // The viewer far along +u looks back along -u: the radiance travelling towards +u. The
        // lines cover the light's bounding box as projected across u (the window's rim is vacuum).
        const double half = 0.5 * ((ww - 2) * std::abs(n.x) + (wh - 2) * std::abs(n.y));
        const int lines = static_cast<int>(std::ceil(2.0 * half / kIntensityLineSpacing));
        for (int k = 0; k < lines; ++k) {
            const double offset = -half + (k + 0.5) * kIntensityLineSpacing;
            marchAttributing(sigma, emission, sourceOf, ww, wh, middle + n * offset + u * reach,
                             u * -1.0, 2.0 * reach, sums);
        }
        for (std::size_t k = 0; k < sources; ++k) {
            tables[k][static_cast<std::size_t>(m)] = {
                static_cast<float>(sums[k * 3] * kIntensityLineSpacing),
                static_cast<float>(sums[k * 3 + 1] * kIntensityLineSpacing),
                static_cast<float>(sums[k * 3 + 2] * kIntensityLineSpacing)};
        }
    }
    // A light much smaller than a pixel is one point (its emission's centroid) with the sum of
    // the tables; from kPointFullRadius to kPointNoneRadius of RMS radius the two blend, so that
    // a growing light does not pop.
    const double point = std::clamp(
        (kPointNoneRadius - light.rmsRadius) / (kPointNoneRadius - kPointFullRadius), 0.0, 1.0);
    light.sources.clear();
    PointSource whole;
    whole.intensity.assign(kIntensityDirections, Rgb{});
    double allWeight = 0, allX = 0, allY = 0;
    for (std::size_t k = 0; k < sources; ++k) {
        if (!(weight[k] > 0)) continue;
        allWeight += weight[k], allX += cx[k], allY += cy[k];
        for (int m = 0; m < kIntensityDirections; ++m) {
            const Rgb& e = tables[k][static_cast<std::size_t>(m)];
            Rgb& sum = whole.intensity[static_cast<std::size_t>(m)];
            sum = {sum.r + e.r, sum.g + e.g, sum.b + e.b};
        }
        if (point >= 1.0) continue;
        PointSource source;
        source.position = {cx[k] / weight[k], cy[k] / weight[k]};
        source.intensity = std::move(tables[k]);
        const auto keep = static_cast<float>(1.0 - point);
        for (Rgb& e : source.intensity) e = {e.r * keep, e.g * keep, e.b * keep};
        light.sources.push_back(std::move(source));
    }
    if (point > 0.0 && allWeight > 0) {
        whole.position = {allX / allWeight, allY / allWeight};
        const auto share = static_cast<float>(point);
        for (Rgb& e : whole.intensity) e = {e.r * share, e.g * share, e.b * share};
        light.sources.push_back(std::move(whole));
    }
}

}  // namespace luxel::gi2d::hrc
