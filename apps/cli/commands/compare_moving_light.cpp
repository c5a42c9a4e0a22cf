#include "commands/compare_moving_light.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "commands/command.h"
#include "commands/error_image.h"
#include "luxel/core/image_io.h"
#include "luxel/gi2d/display.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"
#include "luxel/gi2d/scene2d_edit.h"

namespace luxel::cli {
namespace {

// "0.5,0" -> (0.5, 0).
Result<Vec2d> parseMove(const std::string& text) {
    double dx = 0, dy = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%lf,%lf%c", &dx, &dy, &tail) != 2 || !std::isfinite(dx) ||
        !std::isfinite(dy) || std::abs(dx) > 1e4 || std::abs(dy) > 1e4) {
        return Error("--move '" + text + "' is not DX,DY in pixels (e.g. 0.5,0)");
    }
    return Vec2d{dx, dy};
}

double channelMean(const Image& f, int x, int y) {
    return (f.at(x, y, 0) + f.at(x, y, 1) + f.at(x, y, 2)) / 3.0;
}

Image difference(const Image& b, const Image& a) {
    Image out(a.width(), a.height(), 3);
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) out.setRgb(x, y, b.rgb(x, y) - a.rgb(x, y));
    }
    return out;
}

struct Solver {
    const char* label;
    std::function<Result<Image>(const gi2d::Medium2D&)> solve;
};

}  // namespace

int runCompareMovingLight(const MovingLightArgs& args) {
    auto move = parseMove(args.move);
    if (!move) return reportError(move.error());
    auto sized = loadSizedScene(args.scene, args.size);
    if (!sized) return reportError(sized.error());
    const int light = gi2d::brightestEmitter(sized->scene);
    if (light < 0) return reportError(Error(args.scene + ": no shape emits light to move"));
    auto before = rasterizeSized(*sized, args.scene, gi2d::RasterOptions{}.supersample);
    if (!before) return reportError(before.error());
    gi2d::translateShape(sized->scene.shapes[static_cast<std::size_t>(light)], *move);
    auto after = rasterizeSized(*sized, args.scene, gi2d::RasterOptions{}.supersample);
    if (!after) return reportError(after.error());

    gi2d::ReferenceOptions reference;
    reference.rays = args.rays;
    gi2d::RcOptions vanilla, fix;
    vanilla.merge = gi2d::RcMerge::Vanilla;
    fix.merge = gi2d::RcMerge::BilinearFix;
    const std::vector<Solver> solvers = {
        {"reference", [&](const gi2d::Medium2D& m) { return gi2d::solveReference(m, reference); }},
        {"hrc", [](const gi2d::Medium2D& m) { return gi2d::solveHrc(m); }},
        {"rc-vanilla", [&](const gi2d::Medium2D& m) { return gi2d::solveRc(m, vanilla); }},
        {"rc-bilinear-fix", [&](const gi2d::Medium2D& m) { return gi2d::solveRc(m, fix); }},
    };
    std::vector<Image> changes, firsts;
    for (const Solver& s : solvers) {
        auto a = s.solve(*before);
        if (!a) return reportError(a.error());
        auto b = s.solve(*after);
        if (!b) return reportError(b.error());
        changes.push_back(difference(*b, *a));
        firsts.push_back(std::move(*a));
    }

    const Image& truth = changes[0];
    const int w = truth.width(), h = truth.height();
    double mean = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) mean += channelMean(firsts[0], x, y);
    }
    mean /= static_cast<double>(w) * h;
    if (!(mean > 0)) return reportError(Error(args.scene + ": the reference image is black"));
    // Pixels where the truth changes by less than 0.1% of the mean: any change there is wrong.
    int stable = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) stable += std::abs(channelMean(truth, x, y)) < 1e-3 * mean;
    }
    std::printf("%s at %dx%d, light '%s' moved by (%g, %g) px (reference: %d rays/pixel)\n",
                args.scene.c_str(), w, h,
                sized->scene.shapes[static_cast<std::size_t>(light)].name.c_str(), move->x, move->y,
                args.rays);
    std::printf("%.1f%% of the pixels change by < 0.1%% of the mean in the reference\n",
                100.0 * stable / (static_cast<double>(w) * h));
    std::printf("%-16s %18s %18s %18s\n", "solver", "max change there", "mean change there",
                "RMS wrong change");
    for (std::size_t i = 0; i < solvers.size(); ++i) {
        double worst = 0, sum = 0, squares = 0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const double d = channelMean(changes[i], x, y);
                const double wrong = d - channelMean(truth, x, y);
                squares += wrong * wrong;
                if (std::abs(channelMean(truth, x, y)) >= 1e-3 * mean) continue;
                worst = std::max(worst, std::abs(d));
                sum += std::abs(d);
            }
        }
        std::printf("%-16s %17.3f%% %17.4f%% %17.3f%%\n", solvers[i].label, 100 * worst / mean,
                    stable > 0 ? 100 * sum / stable / mean : 0.0,
                    100 * std::sqrt(squares / (static_cast<double>(w) * h)) / mean);
    }
    std::printf("(changes as %% of the reference's mean fluence)\n");
    if (!args.errorImage.empty()) {
        const double scale = args.errorScalePercent / 100.0;
        std::vector<Image> panels = {
            gi2d::displayImage(*before, firsts[0], ToneMapSettings{}),
            divergingColours(signedRelativeDifference(truth, Image(w, h, 3), mean), scale)};
        for (std::size_t i = 1; i < solvers.size(); ++i) {
            panels.push_back(
                divergingColours(signedRelativeDifference(changes[i], truth, mean), scale));
        }
        if (Status s = writePng(args.errorImage, sideBySide(panels)); !s) {
            return reportError(s.error());
        }
        std::printf(
            "wrote %s (left to right: reference, the reference's change, then hrc, rc vanilla, "
            "rc bilinear fix: change minus the reference's change; white 0, red +%g%%, blue "
            "-%g%% of the mean)\n",
            args.errorImage.c_str(), args.errorScalePercent, args.errorScalePercent);
    }
    return 0;
}

}  // namespace luxel::cli
