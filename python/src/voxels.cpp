// luxel.VoxelWorld (from and to numpy arrays of shape (nx, ny, nz, 4), RGBA uint8), luxel.Camera
// and luxel.VoxelScene.
#include "voxels.h"

#include <pybind11/numpy.h>

#include <cmath>
#include <memory>
#include <string>

#include "arrays.h"
#include "luxel/core/tonemap.h"
#include "luxel/voxel/camera.h"
#include "luxel/voxel/voxel_scene.h"
#include "luxel/voxel/voxel_world.h"

namespace luxel::python {
namespace {

using voxel::Camera;
using voxel::Voxel;
using voxel::VoxelScene;
using voxel::VoxelWorld;

// A world from an array indexed [x, y, z, channel]; voxels whose four bytes are all 0 stay unset
// (the empty world's value), every other voxel is copied, so to_array() gives the array back.
VoxelWorld worldFromArray(py::handle object, int chunkSize) {
    if (!py::isinstance<py::array>(object)) {
        throw LuxelError(
            "VoxelWorld.from_array: expected a numpy array of shape (nx, ny, nz, 4), "
            "dtype uint8");
    }
    const auto array = py::cast<py::array>(object);
    if (array.ndim() != 4 || array.shape(3) != 4) {
        throw LuxelError("VoxelWorld.from_array: shape " + shapeText(array) +
                         " is not (nx, ny, nz, 4) (RGBA per voxel; alpha 0 = empty)");
    }
    if (!array.dtype().is(py::dtype::of<std::uint8_t>())) {
        throw LuxelError("VoxelWorld.from_array: dtype " +
                         py::str(array.dtype()).cast<std::string>() +
                         " is not uint8 (convert with .astype(numpy.uint8))");
    }
    using Bytes = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;
    const Bytes bytes = Bytes::ensure(array);  // a C-contiguous copy only when strided
    const Int3 size{static_cast<int>(array.shape(0)), static_cast<int>(array.shape(1)),
                    static_cast<int>(array.shape(2))};
    for (int axis = 0; axis < 3; ++axis) {
        if (array.shape(axis) < 1 || array.shape(axis) > voxel::kMaxWorldSide) {
            throw LuxelError("VoxelWorld.from_array: shape " + shapeText(array) +
                             ": each side must be in 1.." + std::to_string(voxel::kMaxWorldSide));
        }
    }
    VoxelWorld world = unwrap(VoxelWorld::create(size, chunkSize));
    const std::uint8_t* data = bytes.data();
    py::gil_scoped_release release;
    for (int x = 0; x < size.x; ++x) {
        for (int y = 0; y < size.y; ++y) {
            for (int z = 0; z < size.z; ++z) {
                const std::uint8_t* v =
                    data + ((static_cast<std::size_t>(x) * size.y + y) * size.z + z) * 4;
                if ((v[0] | v[1] | v[2] | v[3]) == 0) continue;
                world.set(x, y, z, Voxel{v[0], v[1], v[2], v[3]});
            }
        }
    }
    world.refreshEmptySpace();
    return world;
}

py::array_t<std::uint8_t> worldToArray(const VoxelWorld& world) {
    const Int3 s = world.size();
    py::array_t<std::uint8_t> out(
        {py::ssize_t{s.x}, py::ssize_t{s.y}, py::ssize_t{s.z}, py::ssize_t{4}});
    std::uint8_t* data = out.mutable_data();
    py::gil_scoped_release release;
    for (int x = 0; x < s.x; ++x) {
        for (int y = 0; y < s.y; ++y) {
            for (int z = 0; z < s.z; ++z) {
                const Voxel v = world.get(x, y, z);
                std::uint8_t* o = data + ((static_cast<std::size_t>(x) * s.y + y) * s.z + z) * 4;
                o[0] = v.r;
                o[1] = v.g;
                o[2] = v.b;
                o[3] = v.a;
            }
        }
    }
    return out;
}

Int3 voxelIndex(const VoxelWorld& world, py::handle index) {
    const auto xyz = py::cast<std::vector<int>>(index);
    if (xyz.size() != 3 || !world.inside(xyz[0], xyz[1], xyz[2])) {
        const Int3 s = world.size();
        throw py::index_error("voxel index must be (x, y, z) inside the world " +
                              std::to_string(s.x) + "x" + std::to_string(s.y) + "x" +
                              std::to_string(s.z));
    }
    return {xyz[0], xyz[1], xyz[2]};
}

Voxel voxelFrom(py::handle value) {
    const auto rgba = py::cast<std::vector<int>>(value);
    if (rgba.size() != 4) throw LuxelError("voxel value must be (r, g, b, a), each 0..255");
    for (int c : rgba) {
        if (c < 0 || c > 255) throw LuxelError("voxel value must be (r, g, b, a), each 0..255");
    }
    return Voxel{static_cast<std::uint8_t>(rgba[0]), static_cast<std::uint8_t>(rgba[1]),
                 static_cast<std::uint8_t>(rgba[2]), static_cast<std::uint8_t>(rgba[3])};
}

py::tuple tupleOf(Vec3d v) {
    return py::make_tuple(v.x, v.y, v.z);
}

void bindWorld(py::module_& m) {
    py::class_<VoxelWorld>(
        m, "VoxelWorld",
        "A dense voxel world of RGBA8 voxels (alpha 0 = empty, 255 = a plain block, 1..254 = a "
        "face texture slot of the scene). Axes: x right, y up, z forward.")
        .def(py::init([](int nx, int ny, int nz, int chunkSize) {
                 return unwrap(VoxelWorld::create({nx, ny, nz}, chunkSize));
             }),
             py::arg("nx"), py::arg("ny"), py::arg("nz"), py::arg("chunk_size") = 32,
             "An empty world of nx x ny x nz voxels.")
        .def_static("from_array", &worldFromArray, py::arg("array"), py::arg("chunk_size") = 32,
                    "A world from a uint8 array of shape (nx, ny, nz, 4) indexed [x, y, z] "
                    "(RGBA). The voxels are copied into luxel's chunked layout.")
        .def("to_array", &worldToArray,
             "The voxels as a new uint8 array (nx, ny, nz, 4) (a copy: the world is stored in "
             "chunks).")
        .def_property_readonly(
            "shape",
            [](const VoxelWorld& w) { return py::make_tuple(w.size().x, w.size().y, w.size().z); })
        .def_property_readonly("chunk_size", &VoxelWorld::chunkSize)
        .def_property_readonly("solid_count", &VoxelWorld::solidCount)
        .def("__getitem__",
             [](const VoxelWorld& w, py::handle index) {
                 const Int3 p = voxelIndex(w, index);
                 const Voxel v = w.get(p.x, p.y, p.z);
                 return py::make_tuple(v.r, v.g, v.b, v.a);
             })
        .def("__setitem__",
             [](VoxelWorld& w, py::handle index, py::handle value) {
                 const Int3 p = voxelIndex(w, index);
                 w.set(p.x, p.y, p.z, voxelFrom(value));
                 w.refreshEmptySpace();
             })
        .def("__eq__", [](const VoxelWorld& a, const VoxelWorld& b) { return a == b; })
        .def("__repr__", [](const VoxelWorld& w) {
            const Int3 s = w.size();
            return "<luxel.VoxelWorld " + std::to_string(s.x) + "x" + std::to_string(s.y) + "x" +
                   std::to_string(s.z) + ", " + std::to_string(w.solidCount()) + " solid>";
        });
}

void bindCamera(py::module_& m) {
    py::class_<Camera>(m, "Camera",
                       "A pinhole camera for voxel worlds. Yaw 0 looks along +z, positive yaw "
                       "turns towards +x; pitch is positive upwards; fov is vertical, degrees.")
        .def(py::init([](py::handle position, double yaw, double pitch, double fov, int width,
                         int height) {
                 return unwrap(Camera::create(vec3From(position, "position"), yaw, pitch, fov,
                                              width, height));
             }),
             py::arg("position"), py::arg("yaw") = 0.0, py::arg("pitch") = 0.0,
             py::arg("fov") = 60.0, py::arg("width") = 256, py::arg("height") = 256)
        .def_static(
            "look_at",
            [](py::handle position, py::handle target, double fov, int width, int height) {
                return unwrap(Camera::lookAt(vec3From(position, "position"),
                                             vec3From(target, "target"), fov, width, height));
            },
            py::arg("position"), py::arg("target"), py::arg("fov") = 60.0, py::arg("width") = 256,
            py::arg("height") = 256)
        .def_property_readonly("position", [](const Camera& c) { return tupleOf(c.position()); })
        .def_property_readonly("forward", [](const Camera& c) { return tupleOf(c.forward()); })
        .def_property_readonly("fov", &Camera::fovYDegrees)
        .def_property_readonly("width", &Camera::width)
        .def_property_readonly("height", &Camera::height);
}

void bindScene(py::module_& m) {
    py::class_<VoxelScene, std::shared_ptr<VoxelScene>>(
        m, "VoxelScene",
        "A voxel scene (docs/scene-format-voxel.md): world, camera, sun, sky, materials and "
        "post-processing. Made by load_scene(path), VoxelScene.from_json(text) or "
        "VoxelScene(world, camera) (default shading).")
        .def(py::init([](const VoxelWorld& world, const Camera& camera) {
                 auto scene = std::make_shared<VoxelScene>();
                 scene->world = world;
                 scene->camera = camera;
                 return scene;
             }),
             py::arg("world"), py::arg("camera"), "A scene of a copy of `world`.")
        .def_static(
            "from_json",
            [](const std::string& text, const std::string& path, int width, int height) {
                Result<VoxelScene> scene = Error("");
                {
                    py::gil_scoped_release release;  // generators run here
                    scene = voxel::parseVoxelScene(text, path, width, height);
                }
                return std::make_shared<VoxelScene>(unwrap(std::move(scene)));
            },
            py::arg("json"), py::arg("path") = "<string>", py::arg("width") = 0,
            py::arg("height") = 0,
            "Parses a voxel scene. `path` names it in errors and resolves the files it names; "
            "width/height > 0 override the camera's image size.")
        .def_property(
            "world", [](VoxelScene& s) -> VoxelWorld& { return s.world; },
            [](VoxelScene& s, const VoxelWorld& world) { s.world = world; },
            py::return_value_policy::reference_internal,
            "The scene's world (edits change the scene; assigning copies).")
        .def_readwrite("camera", &VoxelScene::camera)
        .def_readonly("source_path", &VoxelScene::sourcePath)
        .def_property_readonly(
            "exposure", [](const VoxelScene& s) { return s.post.tone.exposureStops; },
            "The scene's exposure in stops (its \"post\" section), for tonemap().")
        .def_property_readonly(
            "curve", [](const VoxelScene& s) { return toneCurveName(s.post.tone.curve); },
            "The scene's tone curve name (its \"post\" section), for tonemap().")
        .def("__repr__", [](const VoxelScene& s) {
            const Int3 size = s.world.size();
            return "<luxel.VoxelScene world " + std::to_string(size.x) + "x" +
                   std::to_string(size.y) + "x" + std::to_string(size.z) + ", image " +
                   std::to_string(s.camera.width()) + "x" + std::to_string(s.camera.height()) + ">";
        });
}

}  // namespace

Vec3d vec3From(py::handle value, const char* what) {
    std::vector<double> v;
    try {
        v = py::cast<std::vector<double>>(value);
    } catch (const py::cast_error&) {
        throw LuxelError(std::string(what) + ": expected three numbers (x, y, z)");
    }
    if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) {
        throw LuxelError(std::string(what) + ": expected three finite numbers (x, y, z)");
    }
    return {v[0], v[1], v[2]};
}

void bindVoxels(py::module_& m) {
    bindWorld(m);
    bindCamera(m);
    bindScene(m);
}

}  // namespace luxel::python
