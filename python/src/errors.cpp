// luxel.Error: every luxel Error (bad input, missing files, no GPU) and every bad argument the
// bindings find (wrong array shapes, NaN) raises it, with luxel's located one-line message.
// It derives from RuntimeError because luxel's errors are not only bad values: a missing file or
// a machine without a Vulkan device raise it too.
#include "bindings.h"

namespace luxel::python {

void bindErrors(py::module_& m) {
    py::register_exception<LuxelError>(m, "Error", PyExc_RuntimeError);
    m.attr("Error").attr("__doc__") =
        "A luxel error: the message names the problem and where it is, e.g. "
        "'scene.json:3:14: shapes[0].radius: must be > 0, got -4'.";
}

}  // namespace luxel::python
