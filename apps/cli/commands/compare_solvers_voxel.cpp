// `luxel compare-solvers` on a voxel scene: the path tracer is the reference (--spp samples);
// sky visibility (ambient occlusion) and the ray caster with physical lighting are measured
// against it: time, relative L1, RMSE, low-frequency RMSE (8 x 8 pixel block means, the error a
// smooth GI method is judged by: docs/algorithms/voxel-sky-visibility.md) and peak memory.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "commands/command.h"
#include "commands/compare_solvers_run.h"
#include "commands/error_image.h"
#include "commands/render_outputs.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/metrics.h"
#include "luxel/post/label.h"

namespace luxel::cli {
namespace {

constexpr int kBlock = 8;  // pixels per side of the low-frequency blocks

// The mean of each kBlock x kBlock block (partial blocks at the right and bottom edges too).
Image blockMeans(const Image& image) {
    const int w = (image.width() + kBlock - 1) / kBlock, h = (image.height() + kBlock - 1) / kBlock;
    Image out(w, h, image.channels());
    for (int by = 0; by < h; ++by) {
        for (int bx = 0; bx < w; ++bx) {
            const int x1 = std::min(image.width(), (bx + 1) * kBlock);
            const int y1 = std::min(image.height(), (by + 1) * kBlock);
            for (int c = 0; c < image.channels(); ++c) {
                double sum = 0;
                for (int y = by * kBlock; y < y1; ++y)
                    for (int x = bx * kBlock; x < x1; ++x) sum += image.at(x, y, c);
                out.at(bx, by, c) =
                    static_cast<float>(sum / ((x1 - bx * kBlock) * (y1 - by * kBlock)));
            }
        }
    }
    return out;
}

}  // namespace

int compareVoxelSolvers(const VoxelCompareRequest& request) {
    const std::vector<SolverRun> solvers = {
        {"path", {"--solver", "path", "--spp", std::to_string(request.spp), "--backend", "cpu"}},
        {"ao", {"--solver", "ao", "--backend", "cpu"}},
        {"ray-caster", {"--lighting", "physical", "--backend", "cpu"}},
    };
    auto solved = runSolverProcesses(request.scene, request.size, solvers);
    if (!solved) return reportError(solved.error());
    const std::vector<RunOutcome>& runs = *solved;

    const Image& reference = runs[0].fluence;
    const Image referenceBlocks = blockMeans(reference);
    std::printf("%s at %dx%d (reference: path tracer, %d samples/pixel)\n", request.scene.c_str(),
                reference.width(), reference.height(), request.spp);
    std::printf("%-12s %10s %10s %10s %9s %13s %12s\n", "solver", "ms", "rel. L1", "RMSE",
                "RMSE/mean", "low-freq/mean", "peak memory");
    std::vector<std::string> labels;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        auto e = compareImages(runs[i].fluence, reference);
        if (!e) return reportError(e.error());
        auto low = compareImages(blockMeans(runs[i].fluence), referenceBlocks);
        if (!low) return reportError(low.error());
        const double mean = e->meanReference > 0 ? e->meanReference : 1.0;
        std::printf("%-12s %10.1f %10.4f %10.5f %8.2f%% %12.2f%% %12s\n", solvers[i].label,
                    runs[i].solveMs, e->relativeL1, e->rmse, 100.0 * e->rmse / mean,
                    100.0 * low->rmse / mean, formatBytes(runs[i].peakBytes).c_str());
        char error[64];
        std::snprintf(error, sizeof error, ", rel. L1 %.4f", e->relativeL1);
        labels.push_back(std::string(solvers[i].label) + "\n" + formatDuration(runs[i].solveMs) +
                         (i == 0 ? ", " + std::to_string(request.spp) + " spp" : error));
    }
    if (!request.grid.empty()) {
        const int scale = post::panelLabelScale(labels, reference.width());
        std::vector<Image> displays;
        ImageMetadata metadata =
            renderMetadata(request.scene, "compare-solvers", reference.width(), reference.height());
        for (std::size_t i = 0; i < runs.size(); ++i) {
            displays.push_back(runs[i].display);
            post::drawPanelLabel(displays.back(), 0, displays.back().width(), labels[i], scale);
            setMetadata(metadata, "luxel.panel" + std::to_string(i + 1) + "." + solvers[i].label,
                        labels[i].substr(labels[i].find('\n') + 1));
        }
        setMetadata(metadata, "luxel.content", "display, tonemapped; panels left to right");
        if (Status s = writePng(request.grid, sideBySide(displays), PngEncoding::Srgb, metadata);
            !s) {
            return reportError(s.error());
        }
        std::printf("wrote %s (left to right: path tracer, sky visibility, ray caster)\n",
                    request.grid.c_str());
    }
    return 0;
}

}  // namespace luxel::cli
