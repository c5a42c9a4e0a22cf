// Scene files for the 2D solvers: JSON to Scene2D with located errors, and Scene2D back to JSON.
#include "luxel/gi2d/scene2d_json.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <new>
#include <nlohmann/json.hpp>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

#include "core/json_fields.h"
#include "gi2d/scene2d_json_internal.h"
#include "luxel/core/file_io.h"
#include "luxel/core/image_io.h"

namespace luxel::gi2d {
namespace {

// The one JSON toolkit (core/json_fields.h): typed reads, one wording, located errors.
using namespace json;

constexpr double kMaxCoordinate = 1e6;
constexpr double kMaxMaterialValue = 1e30;  // well inside float range
constexpr int kMaxCanvasSize = 65536;

double readCoordinate(const Json& v, const std::string& path) {
    const double x = readNumber(v, path);
    if (std::abs(x) > kMaxCoordinate)
        fail(path, "must be within [-1e6, 1e6], got " + formatNumber(x));
    return x;
}

// A length or size: > 0 and no larger than the coordinate range.
double readLength(const Json& v, const std::string& path) {
    const double x = readNumber(v, path);
    if (!(x > 0)) fail(path, "must be > 0, got " + formatNumber(x));
    if (x > kMaxCoordinate) fail(path, "must be <= 1e6, got " + formatNumber(x));
    return x;
}

// Emission, absorption, intensity, scales: >= 0 and representable as a float.
float readNonNegative(const Json& v, const std::string& path) {
    const double x = readNumber(v, path);
    if (x < 0) fail(path, "must be >= 0, got " + formatNumber(x));
    if (x > kMaxMaterialValue) fail(path, "must be <= 1e30, got " + formatNumber(x));
    return static_cast<float>(x);
}

template <typename ReadOne>
Vec2d readPair(const Json& v, const std::string& path, const char* form, ReadOne readOne) {
    if (!v.is_array() || v.size() != 2) {
        fail(path, std::string("must be ") + form + ", got " + describe(v));
    }
    return {readOne(v[0], element(path, 0)), readOne(v[1], element(path, 1))};
}

Vec2d readPoint(const Json& v, const std::string& path) {
    return readPair(v, path, "[x, y]", readCoordinate);
}

Vec2d readSize(const Json& v, const std::string& path) {
    return readPair(v, path, "[width, height]", readLength);
}

Rgb readRgb(const Json& v, const std::string& path) {
    if (v.is_number()) return Rgb(readNonNegative(v, path));
    if (!v.is_array() || v.size() != 3) {
        fail(path, "must be [r, g, b] or one number, got " + describe(v));
    }
    return {readNonNegative(v[0], element(path, 0)), readNonNegative(v[1], element(path, 1)),
            readNonNegative(v[2], element(path, 2))};
}

// An albedo: one number or [r, g, b], each in [0, 1) (1 would keep light forever in a closed room).
Rgb readAlbedo(const Json& v, const std::string& path) {
    auto readOne = [](const Json& x, const std::string& where) {
        const double a = readNumber(x, where);
        if (!(a >= 0 && a < 1)) fail(where, "must be in [0, 1), got " + formatNumber(a));
        return static_cast<float>(a);
    };
    if (v.is_number()) return Rgb(readOne(v, path));
    if (!v.is_array() || v.size() != 3) {
        fail(path, "must be [r, g, b] or one number, got " + describe(v));
    }
    return {readOne(v[0], element(path, 0)), readOne(v[1], element(path, 1)),
            readOne(v[2], element(path, 2))};
}

Rgb readOptionalAlbedo(const Json& object, const std::string& path, const char* key) {
    const Json* v = find(object, key);
    return v ? readAlbedo(*v, member(path, key)) : Rgb();
}

int readCanvasSize(const Json& v, const std::string& path) {
    const double x = readNumber(v, path);
    if (x != std::floor(x)) fail(path, "must be a whole number, got " + formatNumber(x));
    if (x < 1) fail(path, "must be >= 1, got " + formatNumber(x));
    if (x > kMaxCanvasSize) {
        fail(path, "absurd canvas size " + formatNumber(x) + " (at most " +
                       std::to_string(kMaxCanvasSize) + ")");
    }
    return static_cast<int>(x);
}

Rgb readOptionalRgb(const Json& object, const std::string& path, const char* key) {
    const Json* v = find(object, key);
    return v ? readRgb(*v, member(path, key)) : Rgb();
}

float readOptionalNonNegative(const Json& object, const std::string& path, const char* key,
                              float fallback) {
    const Json* v = find(object, key);
    return v ? readNonNegative(*v, member(path, key)) : fallback;
}

const std::vector<const char*> kTopLevelFields = {"type",       "description",       "canvas",
                                                  "background", "boundary_radiance", "shapes"};
const std::vector<const char*> kBackgroundFields = {"emission", "absorption", "albedo"};
const std::vector<const char*> kMaterialFields = {"emission", "absorption", "opaque", "intensity",
                                                  "albedo"};
const std::vector<const char*> kImageFields = {
    "type",     "name",       "comment",          "position",  "size",
    "emission", "absorption", "absorption_scale", "intensity", "albedo"};

// type, name, comment, the geometry's fields, then the material's.
std::vector<const char*> shapeFields(std::vector<const char*> geometryFields) {
    std::vector<const char*> fields = {"type", "name", "comment"};
    fields.insert(fields.end(), geometryFields.begin(), geometryFields.end());
    fields.insert(fields.end(), kMaterialFields.begin(), kMaterialFields.end());
    return fields;
}

constexpr const char* kKnownTypes = "circle, box, capsule, line, polygon, image";

class SceneReader {
  public:
    explicit SceneReader(const std::string& baseDir) : baseDir_(baseDir) {}

    Scene2D read(const Json& root) {
        if (!root.is_object()) fail("", "a scene must be a JSON object, got " + describe(root));
        checkFields(root, "", kTopLevelFields, "at the top level");
        if (const Json* v = find(root, "type")) {
            // The scene-file reader sends "voxel" documents elsewhere; anything else is a mistake.
            const std::string type = readString(*v, "type");
            if (type != "2d")
                fail("type", "unknown scene type '" + type + "' (known: 2d, voxel, octree)");
        }
        if (const Json* v = find(root, "description")) readString(*v, "description");

        const Json& canvas = require(root, "", "canvas");
        if (!canvas.is_array() || canvas.size() != 2) {
            fail("canvas", "must be [width, height], got " + describe(canvas));
        }
        scene_.width = readCanvasSize(canvas[0], "canvas[0]");
        scene_.height = readCanvasSize(canvas[1], "canvas[1]");

        if (const Json* v = find(root, "background")) {
            requireObject(*v, "background");
            checkFields(*v, "background", kBackgroundFields, "in background");
            scene_.background.emission = readOptionalRgb(*v, "background", "emission");
            scene_.background.absorption = readOptionalRgb(*v, "background", "absorption");
            scene_.background.albedo = readOptionalAlbedo(*v, "background", "albedo");
        }
        scene_.boundaryRadiance = readOptionalRgb(root, "", "boundary_radiance");

        if (const Json* shapes = find(root, "shapes")) {
            if (!shapes->is_array()) fail("shapes", "must be an array, got " + describe(*shapes));
            scene_.shapes.reserve(shapes->size());
            for (std::size_t i = 0; i < shapes->size(); ++i) {
                scene_.shapes.push_back(readShape((*shapes)[i], element("shapes", i)));
            }
        }
        return std::move(scene_);
    }

  private:
    Shape readShape(const Json& j, const std::string& path) {
        requireObject(j, path);
        const std::string type = readString(require(j, path, "type"), member(path, "type"));
        Shape shape;
        if (type == "image") {
            if (find(j, "opaque")) {
                fail(member(path, "opaque"),
                     "is not allowed for image layers (give an absorption image instead)", true);
            }
            checkFields(j, path, kImageFields, "for image");
            shape.material.intensity = readOptionalNonNegative(j, path, "intensity", 1.0f);
            shape.geometry = readImage(j, path);
        } else {
            if (type == "circle") {
                checkFields(j, path, shapeFields({"center", "radius"}), "for circle");
                shape.geometry =
                    Circle{readPoint(require(j, path, "center"), member(path, "center")),
                           readLength(require(j, path, "radius"), member(path, "radius"))};
            } else if (type == "box") {
                checkFields(j, path, shapeFields({"center", "size", "angle", "min", "max"}),
                            "for box");
                shape.geometry = readBox(j, path);
            } else if (type == "capsule" || type == "line") {
                checkFields(j, path, shapeFields({"from", "to", "thickness"}), "for " + type);
                Capsule capsule;
                capsule.from = readPoint(require(j, path, "from"), member(path, "from"));
                capsule.to = readPoint(require(j, path, "to"), member(path, "to"));
                capsule.thickness =
                    readLength(require(j, path, "thickness"), member(path, "thickness"));
                shape.geometry = capsule;
            } else if (type == "polygon") {
                checkFields(j, path, shapeFields({"points"}), "for polygon");
                shape.geometry = readPolygon(j, path);
            } else {
                fail(member(path, "type"),
                     "unknown shape type '" + type + "' (known: " + kKnownTypes + ")");
            }
            shape.material = readMaterial(j, path);
        }
        const Json* name = find(j, "name");
        shape.name = name ? readString(*name, member(path, "name")) : path;
        if (const Json* comment = find(j, "comment")) readString(*comment, member(path, "comment"));
        return shape;
    }

    static Box readBox(const Json& j, const std::string& path) {
        const Json* min = find(j, "min");
        const Json* max = find(j, "max");
        if (!min && !max) {
            Box box;
            box.center = readPoint(require(j, path, "center"), member(path, "center"));
            box.size = readSize(require(j, path, "size"), member(path, "size"));
            if (const Json* angle = find(j, "angle")) {
                box.angleDegrees = readCoordinate(*angle, member(path, "angle"));
            }
            return box;
        }
        for (const char* key : {"center", "size", "angle"}) {
            if (find(j, key)) {
                fail(member(path, key),
                     "cannot be combined with min/max (give either center, size and angle, or "
                     "min and max)",
                     true);
            }
        }
        const Vec2d lo = readPoint(require(j, path, "min"), member(path, "min"));
        const Vec2d hi = readPoint(require(j, path, "max"), member(path, "max"));
        if (!(hi.x > lo.x && hi.y > lo.y)) {
            fail(member(path, "max"), "must be greater than min in x and y, got min [" +
                                          formatNumber(lo.x) + ", " + formatNumber(lo.y) +
                                          "], max [" + formatNumber(hi.x) + ", " +
                                          formatNumber(hi.y) + "]");
        }
        return Box{(lo + hi) * 0.5, hi - lo, 0.0};
    }

    static Polygon readPolygon(const Json& j, const std::string& path) {
        const std::string pointsPath = member(path, "points");
        const Json& points = require(j, path, "points");
        if (!points.is_array())
            fail(pointsPath, "must be an array of [x, y], got " + describe(points));
        if (points.size() < 3) {
            fail(pointsPath, "must have at least 3 points, got " + std::to_string(points.size()));
        }
        Polygon polygon;
        polygon.points.reserve(points.size());
        for (std::size_t k = 0; k < points.size(); ++k) {
            polygon.points.push_back(readPoint(points[k], element(pointsPath, k)));
        }
        return polygon;
    }

    // Without "absorption" or "opaque" a shape is opaque: solid objects are the common case.
    static Material readMaterial(const Json& j, const std::string& path) {
        Material material;
        material.emission = readOptionalRgb(j, path, "emission");
        material.intensity = readOptionalNonNegative(j, path, "intensity", 1.0f);
        material.albedo = readOptionalAlbedo(j, path, "albedo");
        const Json* opaque = find(j, "opaque");
        const Json* absorption = find(j, "absorption");
        const bool isOpaque = opaque && readBool(*opaque, member(path, "opaque"));
        if (isOpaque && absorption) {
            fail(member(path, "absorption"),
                 "cannot be combined with \"opaque\": true (give one or the other)", true);
        }
        if (absorption) {
            material.absorption = readRgb(*absorption, member(path, "absorption"));
        } else if (opaque && !isOpaque) {
            material.absorption = Rgb();
        } else {
            material.absorption = Rgb(kOpaqueAbsorption);
        }
        return material;
    }

    ImageLayer readImage(const Json& j, const std::string& path) {
        ImageLayer layer;
        const Json* position = find(j, "position");
        layer.position = position ? readPoint(*position, member(path, "position")) : Vec2d{};
        const Json* size = find(j, "size");
        layer.size =
            size ? readSize(*size, member(path, "size"))
                 : Vec2d{static_cast<double>(scene_.width), static_cast<double>(scene_.height)};
        layer.absorptionScale = readOptionalNonNegative(j, path, "absorption_scale", 1.0f);
        const Json* emission = find(j, "emission");
        const Json* absorption = find(j, "absorption");
        const Json* albedo = find(j, "albedo");
        if (!emission && !absorption) {
            fail(path, "an image layer needs \"emission\" and/or \"absorption\" (PNG paths)");
        }
        // Check both paths before reading either image, so typos are reported cheaply.
        if (emission) layer.emissionPath = readImagePath(*emission, member(path, "emission"));
        if (absorption) {
            layer.absorptionPath = readImagePath(*absorption, member(path, "absorption"));
        }
        if (albedo) layer.albedoPath = readImagePath(*albedo, member(path, "albedo"));
        if (emission) {
            layer.emission =
                loadImage(layer.emissionPath, member(path, "emission"), PngEncoding::Srgb);
        }
        if (absorption) {
            layer.absorption =
                loadImage(layer.absorptionPath, member(path, "absorption"), PngEncoding::Linear);
        }
        if (albedo) {
            layer.albedo = loadImage(layer.albedoPath, member(path, "albedo"), PngEncoding::Linear);
        }
        return layer;
    }

    static std::string readImagePath(const Json& v, const std::string& path) {
        if (!v.is_string()) fail(path, "must be the path of a PNG file, got " + describe(v));
        std::string file = v.get<std::string>();
        if (file.empty()) fail(path, "must be the path of a PNG file, got an empty string");
        return file;
    }

    std::shared_ptr<const Image> loadImage(const std::string& file, const std::string& path,
                                           PngEncoding encoding) {
        const std::filesystem::path written(file);
        const std::string resolved = written.is_absolute() || baseDir_.empty()
                                         ? file
                                         : (std::filesystem::path(baseDir_) / written).string();
        // The same picture is often used by several layers; read it once.
        const auto key = std::make_pair(resolved, encoding);
        if (const auto it = cache_.find(key); it != cache_.end()) return it->second;
        Result<Image> image = readPng(resolved, encoding);
        if (!image) fail(path, "cannot load image '" + file + "': " + image.error().message());
        auto shared = std::make_shared<const Image>(std::move(image).value());
        cache_.emplace(key, shared);
        return shared;
    }

    const std::string& baseDir_;
    Scene2D scene_;
    std::map<std::pair<std::string, PngEncoding>, std::shared_ptr<const Image>> cache_;
};

// Whole numbers as integers ("256", not "256.0"); they read back as the same double.
Json numberJson(double v) {
    if (std::abs(v) < 1e15 && v == std::floor(v) && !(v == 0 && std::signbit(v))) {
        return static_cast<std::int64_t>(v);
    }
    return v;
}

// A float as the double whose shortest text reads back as the same float ("0.1", not
// "0.10000000149011612"), unless that text would round differently when read back.
Json floatJson(float f) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), f);
    if (ec == std::errc()) {
        double d = 0;
        const auto parsed = std::from_chars(buffer, end, d);
        if (parsed.ec == std::errc() && static_cast<float>(d) == f) return numberJson(d);
    }
    return numberJson(static_cast<double>(f));
}

Json rgbJson(Rgb c) {
    if (c.r == c.g && c.g == c.b) return floatJson(c.r);
    return Json::array({floatJson(c.r), floatJson(c.g), floatJson(c.b)});
}

Json pointJson(Vec2d p) {
    return Json::array({numberJson(p.x), numberJson(p.y)});
}

Json shapeJson(const Shape& shape, std::size_t index) {
    Json j = Json::object();
    j["type"] = geometryTypeName(shape.geometry);
    if (shape.name != element("shapes", index)) j["name"] = shape.name;
    if (const auto* image = std::get_if<ImageLayer>(&shape.geometry)) {
        j["position"] = pointJson(image->position);
        j["size"] = pointJson(image->size);
        if (!image->emissionPath.empty()) j["emission"] = image->emissionPath;
        if (!image->absorptionPath.empty()) j["absorption"] = image->absorptionPath;
        if (!image->albedoPath.empty()) j["albedo"] = image->albedoPath;
        if (image->absorptionScale != 1.0f)
            j["absorption_scale"] = floatJson(image->absorptionScale);
        if (shape.material.intensity != 1.0f) j["intensity"] = floatJson(shape.material.intensity);
        return j;
    }
    if (const auto* circle = std::get_if<Circle>(&shape.geometry)) {
        j["center"] = pointJson(circle->center);
        j["radius"] = numberJson(circle->radius);
    } else if (const auto* box = std::get_if<Box>(&shape.geometry)) {
        j["center"] = pointJson(box->center);
        j["size"] = pointJson(box->size);
        j["angle"] = numberJson(box->angleDegrees);
    } else if (const auto* capsule = std::get_if<Capsule>(&shape.geometry)) {
        j["from"] = pointJson(capsule->from);
        j["to"] = pointJson(capsule->to);
        j["thickness"] = numberJson(capsule->thickness);
    } else if (const auto* polygon = std::get_if<Polygon>(&shape.geometry)) {
        Json points = Json::array();
        for (const Vec2d& p : polygon->points) points.push_back(pointJson(p));
        j["points"] = std::move(points);
    }
    const Material& m = shape.material;
    if (m.emission != Rgb()) j["emission"] = rgbJson(m.emission);
    if (m.absorption == Rgb(kOpaqueAbsorption)) {
        j["opaque"] = true;
    } else {
        j["absorption"] = rgbJson(m.absorption);  // always written: the default is opaque
    }
    if (m.intensity != 1.0f) j["intensity"] = floatJson(m.intensity);
    if (m.albedo != Rgb()) j["albedo"] = rgbJson(m.albedo);
    return j;
}

// Like nlohmann's dump(2), but arrays of numbers stay on one line: "center": [128, 192].
void writeJson(const Json& j, int indent, std::string& out) {
    const auto dumpScalar = [](const Json& v) {
        // Replace invalid UTF-8 (a name set in code may hold any bytes) instead of throwing.
        return v.dump(-1, ' ', false, Json::error_handler_t::replace);
    };
    const bool container = j.is_array() || j.is_object();
    if (!container || j.empty()) {
        out += dumpScalar(j);
        return;
    }
    if (j.is_array() &&
        std::all_of(j.begin(), j.end(), [](const Json& v) { return v.is_number(); })) {
        out += '[';
        for (std::size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + dumpScalar(j[i]);
        out += ']';
        return;
    }
    const std::string inner(static_cast<std::size_t>(indent) + 2, ' ');
    out += j.is_array() ? "[\n" : "{\n";
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
        out += first ? "" : ",\n";
        first = false;
        out += inner;
        if (j.is_object()) out += dumpScalar(Json(it.key())) + ": ";
        writeJson(it.value(), indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + (j.is_array() ? "]" : "}");
}

}  // namespace

Result<Scene2D> parseScene2D(std::string_view text, const std::string& sourceName,
                             const std::string& baseDir) {
    auto root = json::parse(text, sourceName);
    if (!root) return root.error();
    return scene2DFromJson(*root, text, sourceName, baseDir);
}

Result<Scene2D> scene2DFromJson(const json::Json& root, std::string_view text,
                                const std::string& sourceName, const std::string& baseDir) {
    SourceLocation file;
    file.file = sourceName;
    try {
        SceneReader reader(baseDir);
        Scene2D scene = reader.read(root);
        scene.sourcePath = sourceName;
        return scene;
    } catch (const Invalid& invalid) {
        return json::locate(invalid, text, sourceName);
    } catch (const Json::exception& e) {
        return Error(file, json::boundMessage(std::string("invalid JSON: ") + e.what()));
    } catch (const std::bad_alloc&) {
        return Error(file, "out of memory while reading the scene");
    } catch (const std::exception& e) {
        return Error(file, json::boundMessage(e.what()));
    }
}

Result<Scene2D> loadScene2D(const std::string& path) {
    auto text = readFileBytes(path, "scene");
    if (!text) return text.error();
    return parseScene2D(*text, path, std::filesystem::path(path).parent_path().string());
}

std::string sceneToJson(const Scene2D& scene) {
    Json root = Json::object();
    root["canvas"] = Json::array({scene.width, scene.height});
    if (scene.background.emission != Rgb() || scene.background.absorption != Rgb() ||
        scene.background.albedo != Rgb()) {
        root["background"] = {{"emission", rgbJson(scene.background.emission)},
                              {"absorption", rgbJson(scene.background.absorption)}};
        if (scene.background.albedo != Rgb())
            root["background"]["albedo"] = rgbJson(scene.background.albedo);
    }
    if (scene.boundaryRadiance != Rgb())
        root["boundary_radiance"] = rgbJson(scene.boundaryRadiance);
    Json shapes = Json::array();
    for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
        shapes.push_back(shapeJson(scene.shapes[i], i));
    }
    root["shapes"] = std::move(shapes);
    std::string out;
    writeJson(root, 0, out);
    return out + "\n";
}

}  // namespace luxel::gi2d
