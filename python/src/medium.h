// The 2D medium as a Python object (luxel.Medium): its images as numpy views, built from arrays,
// and checked before every solve since the views are writable.
#pragma once

#include <memory>
#include <optional>

#include "bindings.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::python {

// Every value a solver may see: emission finite and >= 0, absorption in [0, kMaxAbsorption],
// scattering and reflectance in [0, 1), images of one size. Errors name the image, the pixel
// and the value ("medium.absorption[y=2, x=5, channel 1]: must be finite, got nan").
Status validateMedium(const gi2d::Medium2D& medium);

// The scene rasterised at the canvas size or width x height (both or neither), GIL released.
std::shared_ptr<gi2d::Medium2D> rasterizeScene(const gi2d::Scene2D& scene, std::optional<int> width,
                                               std::optional<int> height, int supersample);

void bindMedium(py::module_& m);

}  // namespace luxel::python
