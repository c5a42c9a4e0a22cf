// The Python module `luxel` (docs/python.md): scenes, the 2D solvers, voxel worlds and images as
// numpy arrays. Each concept is bound in its own file; this one puts them together.
#include "bindings.h"

PYBIND11_MODULE(luxel, m) {
    m.doc() =
        "luxel: light transport in 2D and voxel worlds. 2D scenes render with the reference, "
        "HRC and RC solvers on the CPU or a Vulkan GPU; voxel worlds are ray cast. Images are "
        "float32 numpy arrays (height, width, channels). See docs/python.md.";
    m.attr("__version__") = LUXEL_VERSION;
    namespace lp = luxel::python;
    lp::bindErrors(m);  // first: the other bindings raise luxel.Error
    lp::bindImages(m);
    lp::bindScene2D(m);
    lp::bindSolvers(m);
    lp::bindVoxels(m);
    lp::bindVoxelRender(m);
    lp::bindScenes(m);
    lp::bindGpu(m);
}
