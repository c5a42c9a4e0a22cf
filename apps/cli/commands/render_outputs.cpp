// Provenance metadata, exposure and the blown-out warning for `luxel render`.
#include "commands/render_outputs.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <vector>

#include "commands/command.h"
#include "commands/scene_warnings.h"
#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"
#include "luxel/core/image_rows.h"

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

// The rows of `base`, plus `add` pixel by pixel when it is given.
ImageRows hdrRows(const Image& base, const Image* add) {
    if (add == nullptr) return rowsOf(base);
    LUXEL_CHECK(add->width() == base.width() && add->height() == base.height() &&
                add->channels() == base.channels());
    ImageRows rows = rowsOf(base);
    rows.image = nullptr;
    rows.read = [&base, add, rowFloats = rows.rowFloats()](int y0, int y1, float* out) {
        const std::size_t first = static_cast<std::size_t>(y0) * rowFloats;
        const std::size_t count = static_cast<std::size_t>(y1 - y0) * rowFloats;
        const float* a = add->data() + first;
        const float* b = base.data() + first;
        for (std::size_t i = 0; i < count; ++i) out[i] = a[i] + b[i];
    };
    return rows;
}

// `hdr` tonemapped strip by strip, then `draw` on each strip (when set).
ImageRows toneMappedRows(const ImageRows& hdr, const ToneMapSettings& tone,
                         const std::function<void(float*, int, int, int)>& draw) {
    ImageRows rows = hdr;
    rows.image = nullptr;
    rows.read = [hdr, tone, draw](int y0, int y1, float* out) {
        hdr.read(y0, y1, out);
        toneMapPixels(out, static_cast<std::size_t>(y1 - y0) * hdr.width, hdr.channels, tone);
        if (draw) draw(out, hdr.width, y0, y1);
    };
    return rows;
}

// Counts the clipped pixels of the rows people look at as they are read for writing: pixels where
// a light source alone shows at white are lights seen directly, not a blown-out picture.
ImageRows countingClipped(const ImageRows& display, const Image* lightSources,
                          const ToneMapSettings& tone, ClippedPixels& count) {
    ImageRows rows = display;
    rows.image = nullptr;  // every strip goes through the count
    rows.read = [display, lightSources, tone, &count](int y0, int y1, float* out) {
        display.read(y0, y1, out);
        const std::size_t pixels = static_cast<std::size_t>(y1 - y0) * display.width;
        std::vector<float> ignore;
        if (lightSources != nullptr) {
            const ImageRows lights = rowsOf(*lightSources);
            std::vector<float> toned(pixels * lights.channels);
            lights.read(y0, y1, toned.data());
            toneMapPixels(toned.data(), pixels, lights.channels, tone);
            const float white = displayWhiteLevel();
            const int colours = lights.channels < 3 ? 1 : 3;  // as Image::rgb reads them
            ignore.resize(pixels);
            for (std::size_t i = 0; i < pixels; ++i) {
                const float* v = &toned[i * lights.channels];
                bool atWhite = false;
                for (int c = 0; c < colours; ++c) atWhite = atWhite || v[c] >= white;
                ignore[i] = atWhite ? 1.0f : 0.0f;
            }
        }
        count.add(out, display.channels, ignore.empty() ? nullptr : ignore.data(), 1, pixels);
    };
    return rows;
}

}  // namespace

Status writeRenderImages(RenderImages images) {
    const ImageRows hdr = hdrRows(
        images.displayHdr != nullptr ? *images.displayHdr : *images.linear, images.displayAdd);
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
    const bool hasDisplay = !images.png.empty();
    ImageRows outRows = outIsPng ? toneMappedRows(rowsOf(*images.linear), images.tone, nullptr)
                                 : rowsOf(*images.linear);
    ImageRows displayRows;
    if (hasDisplay) displayRows = toneMappedRows(hdr, images.tone, images.drawOnDisplay);
    // The picture people look at: --png, else a PNG --out.
    const bool warn = !images.quiet && (hasDisplay || outIsPng);
    ClippedPixels clipped;
    if (warn) {
        ImageRows& looked = hasDisplay ? displayRows : outRows;
        looked = countingClipped(looked, images.lightSources, images.tone, clipped);
    }
    ImageMetadata outMetadata = images.metadata;
    setMetadata(outMetadata, "luxel.content",
                std::string(images.linearName) + (outIsPng ? ", tonemapped" : ", linear"));
    ImageMetadata displayMetadata = images.metadata;
    setMetadata(displayMetadata, "luxel.content", "display, tonemapped");
    std::vector<ImageFile> files;
    if (!images.out.empty()) files.push_back({images.out, nullptr, &outMetadata, &outRows});
    if (hasDisplay) files.push_back({images.png, nullptr, &displayMetadata, &displayRows});
    if (Status s = writeImages(files); !s) return s;
    if (warn && clipped.fraction() > kClippedWarningFraction) {
        char text[256];
        std::snprintf(
            text, sizeof text,
            "%.1f%% of the lit display pixels are clipped to white at exposure %.2f; "
            "try --exposure %.2f (or --exposure auto)",
            100.0 * clipped.fraction(), images.tone.exposureStops,
            autoExposureStops(hasDisplay ? hdr : rowsOf(*images.linear), images.tone.curve));
        printWarning(text);
    }
    return Ok{};
}

}  // namespace luxel::cli
