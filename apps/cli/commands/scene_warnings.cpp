// Warnings for 2D scenes whose emitters cannot emit.
#include "commands/scene_warnings.h"

#include <algorithm>
#include <cstdio>
#include <variant>

namespace luxel::cli {
namespace {

// "red, green and blue", "green": the channels with emission but no absorption.
std::string darkChannels(Rgb emission, Rgb absorption) {
    const char* names[3] = {"red", "green", "blue"};
    const float e[3] = {emission.r, emission.g, emission.b};
    const float a[3] = {absorption.r, absorption.g, absorption.b};
    std::vector<const char*> dark;
    for (int c = 0; c < 3; ++c) {
        if (e[c] > 0.0f && a[c] == 0.0f) dark.push_back(names[c]);
    }
    std::string text;
    for (std::size_t i = 0; i < dark.size(); ++i) {
        if (i > 0) text += i + 1 == dark.size() ? " and " : ", ";
        text += dark[i];
    }
    return text;
}

const char* kWhy =
    "it emits nothing there (a pixel adds E (1 - exp(-absorption * length)) to the light "
    "crossing it); give it absorption > 0, e.g. \"opaque\": true for a solid light";

// Texels of an image layer with emission in a channel whose absorption (times the scale) is 0,
// each emission texel sampled against the absorption texel under its centre (nearest, as the
// rasteriser samples both).
std::size_t silentTexels(const gi2d::ImageLayer& layer) {
    if (!layer.emission || !layer.absorption) return 0;  // emission alone: opaque sprites
    const Image& e = *layer.emission;
    const Image& a = *layer.absorption;
    const int alpha = e.channels() == 4 ? 3 : (e.channels() == 2 ? 1 : -1);
    std::size_t silent = 0;
    for (int y = 0; y < e.height(); ++y) {
        const int ay =
            std::min(a.height() - 1, static_cast<int>((y + 0.5) * a.height() / e.height()));
        for (int x = 0; x < e.width(); ++x) {
            if (alpha >= 0 && e.at(x, y, alpha) <= 0.0f) continue;
            const int ax =
                std::min(a.width() - 1, static_cast<int>((x + 0.5) * a.width() / e.width()));
            const Rgb emission = e.rgb(x, y);
            const Rgb absorption = a.rgb(ax, ay) * layer.absorptionScale;
            if (!darkChannels(emission, absorption).empty()) ++silent;
        }
    }
    return silent;
}

}  // namespace

std::vector<std::string> silentEmitterWarnings(const gi2d::Scene2D& scene) {
    std::vector<std::string> warnings;
    if (const std::string dark =
            darkChannels(scene.background.emission, scene.background.absorption);
        !dark.empty()) {
        warnings.push_back("the background has emission but absorption 0 in " + dark + ": " + kWhy);
    }
    for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
        const gi2d::Shape& shape = scene.shapes[i];
        const std::string label =
            "shapes[" + std::to_string(i) + "]" +
            (shape.name.empty() || shape.name == "shapes[" + std::to_string(i) + "]"
                 ? std::string()
                 : " '" + shape.name + "'");
        if (const auto* layer = std::get_if<gi2d::ImageLayer>(&shape.geometry)) {
            if (const std::size_t n = silentTexels(*layer); n > 0) {
                warnings.push_back(label + " (image layer) has " + std::to_string(n) +
                                   " texels with emission but absorption 0: " + kWhy);
            }
            continue;
        }
        const std::string dark =
            darkChannels(shape.material.scaledEmission(), shape.material.absorption);
        if (!dark.empty()) {
            warnings.push_back(label + " has emission but absorption 0 in " + dark + ": " + kWhy);
        }
    }
    return warnings;
}

void printWarning(const std::string& message) {
    std::fprintf(stderr, "luxel: warning: %s\n", message.c_str());
}

}  // namespace luxel::cli
