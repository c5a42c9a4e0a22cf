// luxel.load_scene: any scene file luxel reads, by its "type" (luxel/scene/scene_file.h): a 2D
// scene becomes a Scene2D, a voxel scene a VoxelScene.
#include <memory>
#include <optional>

#include "bindings.h"
#include "luxel/scene/scene_file.h"

namespace luxel::python {
namespace {

py::object loadScene(const std::string& path, std::optional<int> width, std::optional<int> height) {
    if (width.has_value() != height.has_value()) {
        throw LuxelError("give both width and height, or neither");
    }
    scene::SceneFileOptions options;
    if (width) {
        if (*width < 1 || *height < 1) {
            throw LuxelError("width and height must be >= 1, got " + std::to_string(*width) + "x" +
                             std::to_string(*height));
        }
        options.voxelImageSize = {*width, *height};
    }
    Result<scene::SceneFile> file = Error("");
    {
        py::gil_scoped_release release;  // voxel generators and octree builds run here
        file = scene::loadSceneFile(path, options);
    }
    scene::SceneFile loaded = unwrap(std::move(file));
    switch (loaded.kind()) {
        case scene::SceneKind::TwoD:
            if (width) {
                throw LuxelError(path +
                                 ": width/height set a voxel scene's image size; a 2D scene "
                                 "takes them in rasterize() or render()");
            }
            return py::cast(std::make_shared<gi2d::Scene2D>(std::move(loaded.twoD())));
        case scene::SceneKind::Voxel:
            return py::cast(std::make_shared<voxel::VoxelScene>(std::move(loaded.voxel())));
        case scene::SceneKind::Octree:
            break;
    }
    throw LuxelError(path +
                     ": an octree scene; the Python module renders 2D and voxel scenes (use "
                     "`luxel render` for octree scenes)");
}

}  // namespace

void bindScenes(py::module_& m) {
    m.def("load_scene", &loadScene, py::arg("path"), py::arg("width") = py::none(),
          py::arg("height") = py::none(),
          "Reads a scene file: a Scene2D or a VoxelScene, by the file's \"type\". width/height "
          "set a voxel scene's image size. Errors (luxel.Error) name the file, line:column and "
          "field.");
}

}  // namespace luxel::python
