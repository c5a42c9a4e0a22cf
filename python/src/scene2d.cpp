// luxel.Scene2D: 2D scenes from JSON text (or a dict), back to JSON, and rasterised to a Medium.
#include <memory>
#include <string>

#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/scene2d.h"
#include "luxel/gi2d/scene2d_json.h"
#include "medium.h"

namespace luxel::python {
namespace {

using gi2d::Scene2D;

// JSON text as given, or a dict/list written as JSON by the json module.
std::string jsonText(py::handle source) {
    if (py::isinstance<py::str>(source)) return source.cast<std::string>();
    if (py::isinstance<py::dict>(source)) {
        return py::module_::import("json")
            .attr("dumps")(source, py::arg("indent") = 1)
            .cast<std::string>();
    }
    throw py::type_error("expected JSON text (str) or a dict");
}

Scene2D sceneFromJson(py::handle source, const std::string& name, const std::string& baseDir) {
    return unwrap(gi2d::parseScene2D(jsonText(source), name, baseDir));
}

// Output size: both given, or neither (the scene's canvas).
std::pair<int, int> rasterSize(const Scene2D& scene, std::optional<int> width,
                               std::optional<int> height) {
    if (width.has_value() != height.has_value()) {
        throw LuxelError("give both width and height, or neither (the scene's canvas, " +
                         std::to_string(scene.width) + "x" + std::to_string(scene.height) + ")");
    }
    if (!width) return {scene.width, scene.height};
    check(gi2d::validateCanvasSize(*width, *height));
    return {*width, *height};
}

}  // namespace

// Used by the solver bindings as well (render(scene) rasterises first).
std::shared_ptr<gi2d::Medium2D> rasterizeScene(const Scene2D& scene, std::optional<int> width,
                                               std::optional<int> height, int supersample) {
    const auto [w, h] = rasterSize(scene, width, height);
    if (supersample < 1 || supersample > 64) {
        throw LuxelError("supersample must be in 1..64, got " + std::to_string(supersample));
    }
    Result<gi2d::Medium2D> medium = Error("");
    {
        py::gil_scoped_release release;
        medium = gi2d::rasterize(scene, {w, h, supersample});
    }
    if (!medium) {
        const std::string name = scene.sourcePath.empty() ? "<scene>" : scene.sourcePath;
        throw LuxelError(name + ": " + medium.error().message());
    }
    return std::make_shared<gi2d::Medium2D>(std::move(medium).value());
}

void bindScene2D(py::module_& m) {
    py::class_<Scene2D, std::shared_ptr<Scene2D>>(
        m, "Scene2D",
        "A 2D scene (docs/scene-format-2d.md): a canvas, a background medium and shapes. Made by "
        "load_scene(path) or Scene2D.from_json(text or dict).")
        .def_static("from_json", &sceneFromJson, py::arg("json"), py::arg("name") = "<string>",
                    py::arg("base_dir") = ".",
                    "Parses a scene from JSON text or a dict. `name` is used in error messages "
                    "('<string>:3:14: ...'), `base_dir` resolves image layer paths.")
        .def("to_json", &gi2d::sceneToJson, "The scene as JSON text (from_json reads it back).")
        .def_readonly("width", &Scene2D::width, "Canvas width in pixels.")
        .def_readonly("height", &Scene2D::height, "Canvas height in pixels.")
        .def_readonly("source_path", &Scene2D::sourcePath)
        .def_property_readonly(
            "shape_names",
            [](const Scene2D& scene) {
                std::vector<std::string> names;
                for (const gi2d::Shape& shape : scene.shapes) names.push_back(shape.name);
                return names;
            },
            "The shapes' names, in drawing order.")
        .def_property_readonly("bounces", &gi2d::sceneBounces,
                               "Whether any material has an albedo (light bounces).")
        .def("rasterize", &rasterizeScene, py::arg("width") = py::none(),
             py::arg("height") = py::none(), py::arg("supersample") = 16,
             "The medium the solvers see, at the canvas size or width x height (the scene is "
             "scaled; optical depths stay the same).")
        .def("__repr__", [](const Scene2D& scene) {
            return "<luxel.Scene2D " + std::to_string(scene.width) + "x" +
                   std::to_string(scene.height) + ", " + std::to_string(scene.shapes.size()) +
                   " shapes>";
        });
    bindMedium(m);
}

}  // namespace luxel::python
