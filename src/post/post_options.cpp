// Upscaler names, as the CLI, scene files and the viewer spell them.
#include "luxel/post/post_options.h"

#include "post/sample.h"

namespace luxel::post {

std::optional<Upscaler> parseUpscaler(std::string_view name) {
    if (name == "bilinear") return Upscaler::Bilinear;
    if (name == "edge") return Upscaler::Edge;
    return std::nullopt;
}

const char* upscalerName(Upscaler upscaler) {
    return upscaler == Upscaler::Bilinear ? "bilinear" : "edge";
}

namespace detail {

Image toRgb(const Image& image) {
    if (image.channels() == 3 || image.empty()) return image;
    Image out(image.width(), image.height(), 3);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) out.setRgb(x, y, image.rgb(x, y));
    }
    return out;
}

}  // namespace detail

}  // namespace luxel::post
