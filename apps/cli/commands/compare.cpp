// `luxel compare`: error metrics between a test image and a reference, optional diff picture.
#include <cmath>
#include <cstdio>
#include <memory>

#include "commands/command.h"
#include "commands/scene_warnings.h"
#include "luxel/core/image_io.h"
#include "luxel/core/memory.h"
#include "luxel/core/metrics.h"

namespace luxel::cli {
namespace {

struct CompareArgs {
    std::string test, reference, diff, mask;
    float diffScale = 0.0f;
};

// |a - b| averaged over channels, scaled so that `scale` maps to white (0 = the max error).
Image diffImage(const Image& a, const Image& b, double scale) {
    Image out(a.width(), a.height(), 3);
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            double d = 0;
            for (int c = 0; c < a.channels(); ++c) d += std::abs(a.at(x, y, c) - b.at(x, y, c));
            const float v = static_cast<float>(d / a.channels() / scale);
            out.setRgb(x, y, Rgb(v));
        }
    }
    return out;
}

// "hrc, 512x512, 0.81 s (room.json)" from an image's metadata; empty without luxel's.
std::string describe(const ImageMetadata& metadata) {
    const std::string* solver = findMetadata(metadata, "luxel.solver");
    if (solver == nullptr) return "";
    std::string text = *solver;
    if (const std::string* rays = findMetadata(metadata, "luxel.rays"))
        text += " " + *rays + " rays";
    for (const char* key : {"luxel.canvas", "luxel.render.seconds", "luxel.scene"}) {
        if (const std::string* value = findMetadata(metadata, key)) {
            text += ", " + *value + (std::string(key) == "luxel.render.seconds" ? " s" : "");
        }
    }
    return text;
}

int runCompare(const CompareArgs& args) {
    ImageMetadata testMetadata, referenceMetadata;
    auto a = readImage(args.test, &testMetadata);
    if (!a) return reportError(a.error());
    auto b = readImage(args.reference, &referenceMetadata);
    if (!b) return reportError(b.error());
    if (const std::string text = describe(testMetadata); !text.empty()) {
        std::printf("test          %s\n", text.c_str());
    }
    if (const std::string text = describe(referenceMetadata); !text.empty()) {
        std::printf("reference     %s\n", text.c_str());
    }
    const std::string* testHash = findMetadata(testMetadata, "luxel.scene.fnv1a64");
    const std::string* referenceHash = findMetadata(referenceMetadata, "luxel.scene.fnv1a64");
    if (testHash != nullptr && referenceHash != nullptr && *testHash != *referenceHash) {
        printWarning("the images were rendered from different scene files (FNV-1a " + *testHash +
                     " and " + *referenceHash + ")");
    }
    Image mask;
    if (!args.mask.empty()) {
        auto m = readImage(args.mask);
        if (!m) return reportError(m.error());
        mask = std::move(*m);
    }
    auto errors = compareImages(*a, *b, args.mask.empty() ? nullptr : &mask);
    if (!errors) return reportError(errors.error());
    std::printf("pixels        %zu\n", errors->countedPixels);
    std::printf("RMSE          %.6g  (%.3f%% of reference mean %.6g)\n", errors->rmse,
                errors->meanReference > 0 ? 100.0 * errors->rmse / errors->meanReference : 0.0,
                errors->meanReference);
    std::printf("relative L1   %.6g\n", errors->relativeL1);
    std::printf("max abs error %.6g\n", errors->maxAbsError);
    if (!args.diff.empty()) {
        // The RGB difference and the PNG encoder's 8-bit copy of it.
        const std::uint64_t diffBytes = imageBytes(a->width(), a->height(), 3) * 5 / 4;
        if (Status s = checkMemory(diffBytes, "the difference image"); !s) {
            return reportError(s.error());
        }
        const double scale = args.diffScale > 0        ? args.diffScale
                             : errors->maxAbsError > 0 ? errors->maxAbsError
                                                       : 1.0;
        if (Status s = writePng(args.diff, diffImage(*a, *b, scale), PngEncoding::Linear); !s) {
            return reportError(s.error());
        }
        std::printf("wrote %s (white = %.6g)\n", args.diff.c_str(), scale);
    }
    return 0;
}

}  // namespace

Runner addCompareCommand(CLI::App& app) {
    auto args = std::make_shared<CompareArgs>();
    app.add_option("test", args->test, "image to judge (.exr or .png)")->required();
    app.add_option("reference", args->reference, "reference image")->required();
    app.add_option("--diff", args->diff, "write |test - reference| as a PNG");
    app.add_option("--diff-scale", args->diffScale, "error shown as white (default: max error)")
        ->check(finiteIn(0.0, 1e30));
    app.add_option("--mask", args->mask, "only pixels where this image is > 0.5 count");
    return [args] { return runCompare(*args); };
}

}  // namespace luxel::cli
