// Shared pieces of the Python module (docs/python.md): how luxel's Error becomes the Python
// exception luxel.Error, and the bind functions each file of python/src defines.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <utility>

#include "luxel/core/error.h"

namespace luxel::python {

namespace py = pybind11;

// Thrown by the bindings and translated to luxel.Error with the same one-line message
// ("scene.json:3:14: shapes[0].radius: must be > 0, got -4").
class LuxelError : public std::runtime_error {
  public:
    explicit LuxelError(const std::string& message) : std::runtime_error(message) {}
};

[[noreturn]] inline void raise(const Error& error) {
    throw LuxelError(error.message());
}

// The value of a Result, or luxel.Error with its message.
template <typename T>
T unwrap(Result<T>&& result) {
    if (!result) raise(result.error());
    return std::move(result).value();
}

inline void check(const Status& status) {
    if (!status) raise(status.error());
}

void bindErrors(py::module_& m);
void bindImages(py::module_& m);
void bindScene2D(py::module_& m);
void bindMedium(py::module_& m);
void bindSolvers(py::module_& m);
void bindVoxels(py::module_& m);
void bindVoxelRender(py::module_& m);
void bindScenes(py::module_& m);
void bindGpu(py::module_& m);

}  // namespace luxel::python
