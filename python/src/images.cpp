// Images in and out: reading and writing PNG/EXR, tone mapping and comparison metrics, all on
// float32 numpy arrays of shape (height, width, channels).
#include <cctype>
#include <cmath>
#include <string>

#include "arrays.h"
#include "luxel/core/image_io.h"
#include "luxel/core/metrics.h"
#include "luxel/core/tonemap.h"

namespace luxel::python {
namespace {

PngEncoding parseEncoding(const std::string& name) {
    if (name == "srgb") return PngEncoding::Srgb;
    if (name == "linear") return PngEncoding::Linear;
    throw LuxelError("encoding '" + name + "' is not srgb or linear");
}

bool isPng(const std::string& path) {
    if (path.size() < 4) return false;
    std::string tail = path.substr(path.size() - 4);
    for (char& ch : tail) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return tail == ".png";
}

py::array_t<float> readImage(const std::string& path, const std::string& encoding) {
    const PngEncoding png = parseEncoding(encoding);
    Result<Image> image = Error("");
    {
        py::gil_scoped_release release;
        image = isPng(path) ? readPng(path, png) : luxel::readImage(path);
    }
    return imageToArray(unwrap(std::move(image)));
}

void writeImage(const std::string& path, py::handle array, const std::string& encoding) {
    const PngEncoding png = parseEncoding(encoding);
    const Image image = arrayToImage(array, "image");
    py::gil_scoped_release release;
    // Both writers go through a temporary file renamed over the target when complete.
    check(isPng(path) ? writePng(path, image, png) : luxel::writeImage(path, image));
}

ToneCurve parseCurve(const std::string& name) {
    const auto curve = parseToneCurve(name);
    if (!curve) throw LuxelError("curve '" + name + "' is not clamp, reinhard or aces");
    return *curve;
}

py::array_t<float> toneMapArray(py::handle array, float exposure, const std::string& curve) {
    if (!std::isfinite(exposure)) throw LuxelError("exposure must be finite");
    const ToneMapSettings settings{exposure, parseCurve(curve)};
    const Image hdr = arrayToImage(array, "image");
    return imageToArray(toneMap(hdr, settings));
}

py::dict compareArrays(py::handle a, py::handle b, py::object mask) {
    const Image test = arrayToImage(a, "a"), reference = arrayToImage(b, "b");
    Image maskImage;
    if (!mask.is_none()) maskImage = arrayToImage(mask, "mask");
    const ImageErrors errors =
        unwrap(compareImages(test, reference, mask.is_none() ? nullptr : &maskImage));
    py::dict out;
    out["rmse"] = errors.rmse;
    out["rel_l1"] = errors.relativeL1;
    out["max_abs"] = errors.maxAbsError;
    out["mean_reference"] = errors.meanReference;
    out["counted_pixels"] = errors.countedPixels;
    return out;
}

}  // namespace

ToneMapSettings toneSettings(float exposure, const std::string& curve) {
    if (!std::isfinite(exposure)) throw LuxelError("exposure must be finite");
    return {exposure, parseCurve(curve)};
}

void bindImages(py::module_& m) {
    m.def("read_image", &readImage, py::arg("path"), py::arg("encoding") = "srgb",
          "Reads a PNG or EXR (by extension) as a float32 array (height, width, channels), linear "
          "values. encoding='linear' reads PNG values as data (value / 255) instead of sRGB "
          "colour. The array owns the decoded image (no copy).");
    m.def("write_image", &writeImage, py::arg("path"), py::arg("image"),
          py::arg("encoding") = "srgb",
          "Writes an array (height, width[, channels]) as PNG (8-bit; sRGB-encoded unless "
          "encoding='linear'; values clamped to [0, 1]) or EXR (32-bit float), chosen by the "
          "extension. The file is written to a temporary name and renamed when complete. The "
          "array is copied once.");
    m.def("tonemap", &toneMapArray, py::arg("image"), py::arg("exposure") = 0.0f,
          py::arg("curve") = "aces",
          "Linear HDR -> display-referred linear [0, 1]: 2^exposure, then the curve (clamp, "
          "reinhard or aces) on the first three channels. NaN becomes 0. Returns a new array.");
    m.def("compare", &compareArrays, py::arg("a"), py::arg("b"), py::arg("mask") = py::none(),
          "Errors of test image `a` against reference `b` (same shape): a dict with rmse, rel_l1 "
          "(mean|a-b| / mean|b|), max_abs, mean_reference and counted_pixels. `mask` (height, "
          "width), when given, counts only pixels where it is > 0.5.");
}

}  // namespace luxel::python
