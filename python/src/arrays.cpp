// luxel images <-> numpy arrays (arrays.h).
#include "arrays.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <memory>

#include "luxel/core/image_size.h"

namespace luxel::python {

py::array_t<float> imageToArray(Image image) {
    if (image.empty()) return py::array_t<float>(std::vector<py::ssize_t>{0, 0, 3});
    auto owned = std::make_unique<Image>(std::move(image));
    float* pixels = owned->data();
    const py::ssize_t h = owned->height(), w = owned->width(), c = owned->channels();
    const py::ssize_t f = sizeof(float);
    py::capsule owner(owned.get(), [](void* p) { delete static_cast<Image*>(p); });
    owned.release();  // the capsule deletes it now
    return py::array_t<float>({h, w, c}, {w * c * f, c * f, f}, pixels, owner);
}

py::array_t<float> imageView(Image& image, py::handle owner) {
    if (image.empty()) return py::array_t<float>(std::vector<py::ssize_t>{0, 0, 3});
    const py::ssize_t h = image.height(), w = image.width(), c = image.channels();
    const py::ssize_t f = sizeof(float);
    return py::array_t<float>({h, w, c}, {w * c * f, c * f, f}, image.data(), owner);
}

std::string shapeText(const py::array& array) {
    std::string text = "(";
    for (py::ssize_t i = 0; i < array.ndim(); ++i) {
        if (i > 0) text += ", ";
        text += std::to_string(array.shape(i));
    }
    return text + (array.ndim() == 1 ? ",)" : ")");
}

Image arrayToImage(py::handle array, const std::string& what) {
    using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;
    if (py::isinstance<py::array>(array)) {
        const auto kind = py::cast<py::array>(array).dtype().kind();
        if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b') {
            throw LuxelError(what + ": dtype " +
                             py::str(py::cast<py::array>(array).dtype()).cast<std::string>() +
                             " is not a number type");
        }
    }
    FloatArray values = FloatArray::ensure(array);
    if (!values) throw LuxelError(what + ": expected an array of numbers");
    const bool grey = values.ndim() == 2;
    if (values.ndim() != 2 && values.ndim() != 3) {
        throw LuxelError(what + ": shape " + shapeText(values) +
                         " is not (height, width) or (height, width, channels)");
    }
    const py::ssize_t h = values.shape(0), w = values.shape(1);
    const py::ssize_t c = grey ? 1 : values.shape(2);
    if (c < 1 || c > 4) {
        throw LuxelError(what + ": shape " + shapeText(values) + " has " + std::to_string(c) +
                         " channels; 1 to 4 are supported");
    }
    if (h < 1 || w < 1 || h > kMaxImageSide || w > kMaxImageSide) {
        throw LuxelError(what + ": shape " + shapeText(values) + ": each side must be in 1.." +
                         std::to_string(kMaxImageSide));
    }
    Image image(static_cast<int>(w), static_cast<int>(h), static_cast<int>(c));
    std::memcpy(image.data(), values.data(), image.size() * sizeof(float));
    return image;
}

}  // namespace luxel::python
