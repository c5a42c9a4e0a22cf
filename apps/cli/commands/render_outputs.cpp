// Provenance metadata, exposure and the blown-out warning for `luxel render`.
#include "commands/render_outputs.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <vector>

#include "commands/command.h"
#include "commands/scene_warnings.h"
#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"

namespace luxel::cli {

Result<ExposureFlag> parseExposureFlag(const std::string& text) {
    ExposureFlag flag;
    if (text.empty()) return flag;
    if (text == "auto") {
        flag.automatic = true;
        return flag;
    }
    try {
        std::size_t used = 0;
        const double stops = std::stod(text, &used);
        if (used == text.size() && std::isfinite(stops) && stops >= -64.0 && stops <= 64.0) {
            flag.stops = static_cast<float>(stops);
            return flag;
        }
    } catch (const std::exception&) {
        // reported below
    }
    // Worded as the other number options' checks (common/number_options.h).
    return Error("--exposure: '" + text + "' is not a finite number in [-64, 64] or auto");
}

ImageMetadata renderMetadata(const std::string& scenePath, const std::string& solver, int width,
                             int height) {
    ImageMetadata metadata;
    setMetadata(metadata, "luxel.version", LUXEL_VERSION);
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    char date[32] = "";
    if (gmtime_r(&now, &utc) != nullptr)
        std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
    setMetadata(metadata, "luxel.date", date);
    setMetadata(metadata, "luxel.scene", std::filesystem::path(scenePath).filename().string());
    // The scene was read moments ago; should it have gone since, the hash is left out.
    if (auto bytes = readFileBytes(scenePath, "scene")) {
        setMetadata(metadata, "luxel.scene.fnv1a64", fnv1a64Hex(*bytes));
    }
    setMetadata(metadata, "luxel.solver", solver);
    setMetadata(metadata, "luxel.canvas", std::to_string(width) + "x" + std::to_string(height));
    return metadata;
}

void setNumber(ImageMetadata& metadata, const std::string& key, double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    setMetadata(metadata, key, text);
}

namespace {

// A blown-out picture: more than kClippedWarningFraction of its pixels at white.
void warnIfClipped(const Image& display, const Image& hdr, const ToneMapSettings& tone,
                   const Image* lightSources) {
    // A light at white is not a blown-out picture; only what it lights counts.
    Image whiteLights;
    if (lightSources != nullptr) {
        whiteLights = toneMap(*lightSources, tone);
        const float white = displayWhiteLevel();
        for (int y = 0; y < whiteLights.height(); ++y) {
            for (int x = 0; x < whiteLights.width(); ++x) {
                const Rgb v = whiteLights.rgb(x, y);
                const bool lightAtWhite = v.r >= white || v.g >= white || v.b >= white;
                whiteLights.setRgb(x, y, Rgb(lightAtWhite ? 1.0f : 0.0f));
            }
        }
    }
    const double clipped =
        clippedFraction(display, lightSources != nullptr ? &whiteLights : nullptr);
    if (clipped <= kClippedWarningFraction) return;
    char text[256];
    std::snprintf(text, sizeof text,
                  "%.1f%% of the lit display pixels are clipped to white at exposure %.2f; try "
                  "--exposure %.2f (or --exposure auto)",
                  100.0 * clipped, tone.exposureStops, autoExposureStops(hdr, tone.curve));
    printWarning(text);
}

}  // namespace

Status writeRenderImages(RenderImages images) {
    const Image& hdr = images.displayHdr != nullptr ? *images.displayHdr : *images.linear;
    if (images.autoExposure) {
        images.tone.exposureStops = autoExposureStops(hdr, images.tone.curve);
        if (!images.quiet) {
            std::printf("  exposure auto: %.2f stops\n", images.tone.exposureStops);
        }
    }
    setNumber(images.metadata, "luxel.exposure", images.tone.exposureStops);
    setMetadata(images.metadata, "luxel.exposure.auto", images.autoExposure ? "yes" : "no");
    setMetadata(images.metadata, "luxel.tonemap", toneCurveName(images.tone.curve));

    const bool outIsPng = hasExtension(images.out, ".png");
    Image outImage;
    if (outIsPng) outImage = toneMap(*images.linear, images.tone);
    Image display;
    if (!images.png.empty()) {
        display = toneMap(hdr, images.tone);
        if (images.drawOnDisplay) images.drawOnDisplay(display);
    }
    // The picture people look at: --png, else a PNG --out.
    if (!images.quiet && (!display.empty() || outIsPng)) {
        warnIfClipped(display.empty() ? outImage : display, display.empty() ? *images.linear : hdr,
                      images.tone, images.lightSources);
    }
    ImageMetadata outMetadata = images.metadata;
    setMetadata(outMetadata, "luxel.content",
                std::string(images.linearName) + (outIsPng ? ", tonemapped" : ", linear"));
    ImageMetadata displayMetadata = images.metadata;
    setMetadata(displayMetadata, "luxel.content", "display, tonemapped");
    std::vector<ImageFile> files;
    if (!images.out.empty()) {
        files.push_back({images.out, outIsPng ? &outImage : images.linear, &outMetadata});
    }
    if (!images.png.empty()) files.push_back({images.png, &display, &displayMetadata});
    return writeImages(files);
}

}  // namespace luxel::cli
