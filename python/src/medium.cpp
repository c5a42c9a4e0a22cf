// luxel.Medium (medium.h).
#include "medium.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "arrays.h"
#include "luxel/gi2d/display.h"

namespace luxel::python {
namespace {

using gi2d::Medium2D;

std::string formatValue(float v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(v));
    return text;
}

// Each value of a 3-channel image in [low, high] (high exclusive when `openHigh`).
Status checkRange(const Image& image, const char* name, float low, float high, bool openHigh,
                  int width, int height) {
    if (image.width() != width || image.height() != height || image.channels() != 3) {
        return Error(std::string("medium.") + name + ": " + std::to_string(image.width()) + "x" +
                     std::to_string(image.height()) + "x" + std::to_string(image.channels()) +
                     ", expected " + std::to_string(width) + "x" + std::to_string(height) + "x3");
    }
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const float v = image.at(x, y, c);
                const bool finite = std::isfinite(v);
                if (finite && v >= low && (openHigh ? v < high : v <= high)) continue;
                const std::string where = std::string("medium.") + name +
                                          "[y=" + std::to_string(y) + ", x=" + std::to_string(x) +
                                          ", channel " + std::to_string(c) + "]: ";
                if (!finite) return Error(where + "must be finite, got " + formatValue(v));
                return Error(where + "must be in [" + formatValue(low) + ", " + formatValue(high) +
                             (openHigh ? ")" : "]") + ", got " + formatValue(v));
            }
        }
    }
    return Ok{};
}

Rgb rgbFrom(py::handle value, const char* what) {
    const auto v = py::cast<std::vector<float>>(value);
    if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]) ||
        v[0] < 0 || v[1] < 0 || v[2] < 0) {
        throw LuxelError(std::string(what) + ": expected three finite values >= 0");
    }
    return {v[0], v[1], v[2]};
}

// An image argument of exactly (height, width, 3), or (height, width) spread to RGB.
Image rgbImage(py::handle array, const std::string& what) {
    Image image = arrayToImage(array, what);
    if (image.channels() == 3) return image;
    if (image.channels() != 1) {
        throw LuxelError(what + ": has " + std::to_string(image.channels()) +
                         " channels; expected (height, width, 3) or (height, width)");
    }
    Image rgb(image.width(), image.height(), 3);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) rgb.setRgb(x, y, Rgb(image.at(x, y, 0)));
    }
    return rgb;
}

std::shared_ptr<Medium2D> mediumFromArrays(py::handle emission, py::handle absorption,
                                           py::handle boundary, py::handle scattering,
                                           py::handle reflectance) {
    auto medium = std::make_shared<Medium2D>();
    medium->emission = rgbImage(emission, "emission");
    medium->absorption = rgbImage(absorption, "absorption");
    medium->boundaryRadiance = rgbFrom(boundary, "boundary");
    if (!scattering.is_none()) medium->scattering = rgbImage(scattering, "scattering");
    if (!reflectance.is_none()) medium->reflectance = rgbImage(reflectance, "reflectance");
    check(validateMedium(*medium));
    return medium;
}

}  // namespace

Status validateMedium(const Medium2D& m) {
    const int w = m.width(), h = m.height();
    if (Status s = checkRange(m.emission, "emission", 0.0f, INFINITY, false, w, h); !s) return s;
    if (Status s = checkRange(m.absorption, "absorption", 0.0f, gi2d::kMaxAbsorption, false, w, h);
        !s) {
        return s;
    }
    for (float v : {m.boundaryRadiance.r, m.boundaryRadiance.g, m.boundaryRadiance.b}) {
        if (!std::isfinite(v) || v < 0) {
            return Error("medium.boundary: must be finite and >= 0, got " + formatValue(v));
        }
    }
    // Either bounce image may be empty (0x0) when nothing in the scene needs it.
    if (!m.scattering.empty()) {
        if (Status s = checkRange(m.scattering, "scattering", 0.0f, 1.0f, true, w, h); !s) {
            return s;
        }
    }
    if (m.reflectance.empty()) return Ok{};
    return checkRange(m.reflectance, "reflectance", 0.0f, 1.0f, true, w, h);
}

void bindMedium(py::module_& m) {
    py::class_<Medium2D, std::shared_ptr<Medium2D>>(
        m, "Medium",
        "The per-pixel medium the 2D solvers work on: emission (radiance) and absorption (per "
        "pixel length), RGB, and light from outside the canvas. The image properties are "
        "writable float32 views (height, width, 3) of the medium itself (no copy); edits are "
        "checked at the next render.")
        .def_static("from_arrays", &mediumFromArrays, py::arg("emission"), py::arg("absorption"),
                    py::arg("boundary") = py::make_tuple(0.0f, 0.0f, 0.0f),
                    py::arg("scattering") = py::none(), py::arg("reflectance") = py::none(),
                    "A medium from arrays (height, width, 3) or (height, width): emission >= 0, "
                    "absorption in [0, 64] per pixel; scattering (medium albedo) and reflectance "
                    "(opaque surfaces) in [0, 1) make light bounce. Each array is copied once.")
        .def_property_readonly("width", &Medium2D::width)
        .def_property_readonly("height", &Medium2D::height)
        .def_property_readonly("bounces", &Medium2D::bounces,
                               "Whether light bounces (scattering/reflectance images present).")
        .def_property(
            "boundary",
            [](const Medium2D& medium) {
                const Rgb b = medium.boundaryRadiance;
                return py::make_tuple(b.r, b.g, b.b);
            },
            [](Medium2D& medium, py::handle value) {
                medium.boundaryRadiance = rgbFrom(value, "boundary");
            },
            "Radiance arriving from outside the canvas (r, g, b).")
        .def_property_readonly(
            "emission",
            [](py::object self) { return imageView(self.cast<Medium2D&>().emission, self); })
        .def_property_readonly(
            "absorption",
            [](py::object self) { return imageView(self.cast<Medium2D&>().absorption, self); })
        .def_property_readonly(
            "scattering",
            [](py::object self) -> py::object {
                Medium2D& medium = self.cast<Medium2D&>();
                if (medium.scattering.empty()) return py::none();
                return imageView(medium.scattering, self);
            },
            "Single-scattering albedo per pixel, or None when no medium scatters.")
        .def_property_readonly(
            "reflectance",
            [](py::object self) -> py::object {
                Medium2D& medium = self.cast<Medium2D&>();
                if (medium.reflectance.empty()) return py::none();
                return imageView(medium.reflectance, self);
            },
            "Diffuse reflectance of opaque pixels, or None when no surface reflects.")
        .def(
            "validate", [](const Medium2D& medium) { check(validateMedium(medium)); },
            "Raises luxel.Error naming the first value a solver would refuse.")
        .def("__repr__", [](const Medium2D& medium) {
            return "<luxel.Medium " + std::to_string(medium.width()) + "x" +
                   std::to_string(medium.height()) + (medium.bounces() ? ", bounces>" : ">");
        });

    m.def(
        "display",
        [](const Medium2D& medium, py::handle fluence, float exposure, const std::string& curve) {
            check(validateMedium(medium));
            const Image light = arrayToImage(fluence, "fluence");
            if (light.width() != medium.width() || light.height() != medium.height() ||
                light.channels() != 3) {
                throw LuxelError("fluence: shape (" + std::to_string(light.height()) + ", " +
                                 std::to_string(light.width()) + ", " +
                                 std::to_string(light.channels()) +
                                 ") does not match the medium (" + std::to_string(medium.height()) +
                                 ", " + std::to_string(medium.width()) + ", 3)");
            }
            return imageToArray(gi2d::displayImage(medium, light, toneSettings(exposure, curve)));
        },
        py::arg("medium"), py::arg("fluence"), py::arg("exposure") = 0.0f,
        py::arg("curve") = "aces",
        "The picture people look at: emission (the lights themselves) plus fluence, tone mapped "
        "to linear [0, 1] (write_image to PNG encodes it as sRGB).");
}

}  // namespace luxel::python
