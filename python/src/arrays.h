// luxel images <-> numpy arrays. luxel images go out without a copy: the array owns the image
// (through a capsule) and points at its pixels. Arrays come in with one copy, since a luxel Image
// owns its pixels; a C-contiguous float32 array is copied as is, anything else converted first.
#pragma once

#include <pybind11/numpy.h>

#include <string>

#include "bindings.h"
#include "luxel/core/image.h"
#include "luxel/core/tonemap.h"

namespace luxel::python {

// A float32 array of shape (height, width, channels) that takes the image over (no copy).
py::array_t<float> imageToArray(Image image);

// A writable view of `image` (shape (height, width, channels)) that keeps `owner` alive; for
// images that are members of a bound object.
py::array_t<float> imageView(Image& image, py::handle owner);

// An Image from a numeric array of shape (height, width) or (height, width, channels) with 1..4
// channels. `what` names the argument in errors ("image: shape (3,) is not ...").
Image arrayToImage(py::handle array, const std::string& what);

// Exposure (finite, in stops) and a curve name ("clamp", "reinhard", "aces") as tone settings.
ToneMapSettings toneSettings(float exposure, const std::string& curve);

// "(2, 3, 4)" for messages.
std::string shapeText(const py::array& array);

}  // namespace luxel::python
