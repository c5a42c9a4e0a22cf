// Tests for 2D scene files: the JSON source map, parsing of every shape type with its defaults,
// located error messages, loading from disk, and the sceneToJson round trip.
#include "luxel/gi2d/scene2d_json.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "core/json_source_map.h"
#include "luxel/core/image_io.h"
#include "support/temp_dir.h"

namespace luxel::gi2d {
namespace {

namespace fs = std::filesystem;

// ---- JsonSourceMap --------------------------------------------------------------------------

TEST(JsonSourceMap, RecordsValuesAndKeysOfNestedContainers) {
    const std::string text =
        "{\n"
        "  \"canvas\": [512, 384],\n"
        "  \"shapes\": [\n"
        "    {\"type\": \"circle\", \"radius\": -4},\n"
        "    [1, [2, 3]]\n"
        "  ]\n"
        "}\n";
    const JsonSourceMap map = JsonSourceMap::build(text);
    auto at = [&](const std::string& path) {
        const SourceLocation where = map.locate(path);
        return std::to_string(where.line) + ":" + std::to_string(where.column);
    };
    EXPECT_EQ(at(""), "1:1");
    EXPECT_EQ(at("canvas"), "2:13");
    EXPECT_EQ(at("canvas[0]"), "2:14");
    EXPECT_EQ(at("canvas[1]"), "2:19");
    EXPECT_EQ(at("shapes"), "3:13");
    EXPECT_EQ(at("shapes[0]"), "4:5");
    EXPECT_EQ(at("shapes[0].type"), "4:14");
    EXPECT_EQ(at("shapes[0].radius"), "4:34");
    EXPECT_EQ(at("shapes[1]"), "5:5");
    EXPECT_EQ(at("shapes[1][1][1]"), "5:13");
    const SourceLocation key = map.locateKey("shapes[0].radius");
    EXPECT_EQ(key.line, 4);
    EXPECT_EQ(key.column, 24);
    EXPECT_EQ(key.field, "shapes[0].radius");
    // An array element's "key" is the element itself.
    EXPECT_EQ(map.locateKey("canvas[1]").column, 19);
}

TEST(JsonSourceMap, MissingPathsFallBackToTheNearestParent) {
    const JsonSourceMap map = JsonSourceMap::build("{\"shapes\": [{\"type\": \"box\"}]}");
    const SourceLocation where = map.locate("shapes[0].size[1]");
    EXPECT_EQ(where.field, "shapes[0].size[1]");
    EXPECT_EQ(where.line, 1);
    EXPECT_EQ(where.column, 13);  // the shape object
    EXPECT_EQ(map.locate("nothing").column, 1);
}

TEST(JsonSourceMap, HandlesEscapesAndCountsUtf8CodePoints) {
    // Escaped quotes and backslashes must not end strings early; keys are unescaped.
    const std::string text =
        "{\"a\\\"b\": \"x\\\\\", \"\\u00e9t\\u00E9\": 1,\n"
        " \"\xC3\xA9\xE2\x82\xAC\": [\"\xF0\x9F\x98\x80\", 7], \"\\ud83d\\ude00\": {\"k\": 2}}";
    const JsonSourceMap map = JsonSourceMap::build(text);
    EXPECT_TRUE(map.contains("a\"b"));
    EXPECT_EQ(map.locate("a\"b").column, 10);
    EXPECT_TRUE(map.contains("\xC3\xA9t\xC3\xA9"));
    EXPECT_EQ(map.locate("\xC3\xA9t\xC3\xA9").column, 34);
    // Line 2: ' "é€": ["😀", 7]' - é, € and 😀 are one column each.
    EXPECT_EQ(map.locate("\xC3\xA9\xE2\x82\xAC[1]").line, 2);
    EXPECT_EQ(map.locate("\xC3\xA9\xE2\x82\xAC[1]").column, 14);
    EXPECT_EQ(map.locate("\xF0\x9F\x98\x80.k").column, 40);
}

TEST(JsonSourceMap, ByteOrderMarkTakesNoColumn) {
    const JsonSourceMap map = JsonSourceMap::build("\xEF\xBB\xBF{\"a\": 1}");
    EXPECT_EQ(map.locate("a").column, 7);
}

TEST(JsonSourceMap, DeepNestingIsScannedButNotRecorded) {
    const int depth = 100000;
    const std::string text = std::string(depth, '[') + "1" + std::string(depth, ']');
    const JsonSourceMap map = JsonSourceMap::build(text);
    EXPECT_EQ(map.size(), static_cast<std::size_t>(JsonSourceMap::kMaxRecordedDepth) + 1);
    EXPECT_EQ(map.locate("[0][0]").column, 3);
}

TEST(JsonSourceMap, TextPositions) {
    const std::string text = "ab\n\xC3\xA9x\ny";
    EXPECT_EQ(textPositionAt(text, 0).line, 1);
    EXPECT_EQ(textPositionAt(text, 1).column, 2);
    EXPECT_EQ(textPositionAt(text, 3).line, 2);
    EXPECT_EQ(textPositionAt(text, 5).column, 2);  // 'x' after a two-byte 'é'
    EXPECT_EQ(textPositionAt(text, 7).line, 3);
    EXPECT_EQ(textPositionAt(text, 100).column, 2);  // clamped to the end
    // nlohmann's parse_error::byte counts the bytes read, so the culprit is the byte before.
    EXPECT_EQ(jsonParseErrorPosition(text, 6).column, 2);
    EXPECT_EQ(jsonParseErrorPosition(text, 0).column, 1);
}

TEST(JsonSourceMap, FindsNonFiniteNumbersOutsideStrings) {
    EXPECT_EQ(findNonFiniteJsonNumber("{\"1e999\": [1, -2e5, -1e999]}"), 20u);
    EXPECT_FALSE(findNonFiniteJsonNumber("[1e308, \"9e999\"]").has_value());
}

// ---- Parsing valid scenes -------------------------------------------------------------------

Scene2D parseOk(std::string_view text, const std::string& baseDir = "") {
    Result<Scene2D> scene = parseScene2D(text, "test.json", baseDir);
    EXPECT_TRUE(scene.ok()) << scene.error().message();
    return scene.ok() ? std::move(scene).value() : Scene2D{};
}

TEST(Scene2DJson, MinimalSceneUsesDefaults) {
    const Scene2D scene = parseOk(R"({"canvas": [512, 384]})");
    EXPECT_EQ(scene.width, 512);
    EXPECT_EQ(scene.height, 384);
    EXPECT_EQ(scene.background.emission, Rgb());
    EXPECT_EQ(scene.background.absorption, Rgb());
    EXPECT_EQ(scene.boundaryRadiance, Rgb());
    EXPECT_TRUE(scene.shapes.empty());
    EXPECT_EQ(scene.sourcePath, "test.json");
}

TEST(Scene2DJson, TopLevelFields) {
    const Scene2D scene = parseOk(R"({
        "description": "a test",
        "canvas": [1, 65536],
        "background": {"emission": [0.1, 0.2, 0.3], "absorption": 0.01},
        "boundary_radiance": 2,
        "shapes": []
    })");
    EXPECT_EQ(scene.width, 1);
    EXPECT_EQ(scene.height, 65536);
    EXPECT_EQ(scene.background.emission, Rgb(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(scene.background.absorption, Rgb(0.01f));
    EXPECT_EQ(scene.boundaryRadiance, Rgb(2.0f));
}

TEST(Scene2DJson, EveryGeometricShapeType) {
    const Scene2D scene = parseOk(R"({"canvas": [100, 80], "shapes": [
        {"type": "circle", "center": [10, 20.5], "radius": 3},
        {"type": "box", "center": [50, 40], "size": [20, 10], "angle": 30},
        {"type": "box", "min": [1, 2], "max": [5, 10]},
        {"type": "capsule", "from": [0, 0], "to": [10, -5], "thickness": 2},
        {"type": "line", "from": [1, 1], "to": [1, 1], "thickness": 0.5},
        {"type": "polygon", "points": [[0, 0], [10, 0], [5, 8], [-3, 4]]}
    ]})");
    ASSERT_EQ(scene.shapes.size(), 6u);
    const auto& circle = std::get<Circle>(scene.shapes[0].geometry);
    EXPECT_EQ(circle.center, (Vec2d{10, 20.5}));
    EXPECT_EQ(circle.radius, 3);
    const auto& box = std::get<Box>(scene.shapes[1].geometry);
    EXPECT_EQ(box.center, (Vec2d{50, 40}));
    EXPECT_EQ(box.size, (Vec2d{20, 10}));
    EXPECT_EQ(box.angleDegrees, 30);
    const auto& minMax = std::get<Box>(scene.shapes[2].geometry);
    EXPECT_EQ(minMax.center, (Vec2d{3, 6}));
    EXPECT_EQ(minMax.size, (Vec2d{4, 8}));
    EXPECT_EQ(minMax.angleDegrees, 0);
    const auto& capsule = std::get<Capsule>(scene.shapes[3].geometry);
    EXPECT_EQ(capsule.from, (Vec2d{0, 0}));
    EXPECT_EQ(capsule.to, (Vec2d{10, -5}));
    EXPECT_EQ(capsule.thickness, 2);
    const auto& line = std::get<Capsule>(scene.shapes[4].geometry);
    EXPECT_EQ(line.thickness, 0.5);
    EXPECT_STREQ(geometryTypeName(scene.shapes[4].geometry), "capsule");
    const auto& polygon = std::get<Polygon>(scene.shapes[5].geometry);
    ASSERT_EQ(polygon.points.size(), 4u);
    EXPECT_EQ(polygon.points[3], (Vec2d{-3, 4}));
    for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
        EXPECT_EQ(scene.shapes[i].name, "shapes[" + std::to_string(i) + "]");
    }
}

TEST(Scene2DJson, MaterialDefaultsAndForms) {
    const Scene2D scene = parseOk(R"({"canvas": [10, 10], "shapes": [
        {"type": "circle", "center": [5, 5], "radius": 1},
        {"type": "circle", "center": [5, 5], "radius": 1, "absorption": 0},
        {"type": "circle", "center": [5, 5], "radius": 1, "opaque": false},
        {"type": "circle", "center": [5, 5], "radius": 1, "opaque": true, "emission": 2},
        {"type": "circle", "center": [5, 5], "radius": 1, "opaque": false,
         "absorption": [0.1, 0.2, 0.3], "emission": [1, 0.5, 0], "intensity": 4,
         "name": "lamp", "comment": "ignored"}
    ]})");
    ASSERT_EQ(scene.shapes.size(), 5u);
    // Neither "absorption" nor "opaque": a solid object.
    EXPECT_EQ(scene.shapes[0].material.absorption, Rgb(kOpaqueAbsorption));
    EXPECT_EQ(scene.shapes[0].material.emission, Rgb());
    EXPECT_EQ(scene.shapes[0].material.intensity, 1.0f);
    EXPECT_EQ(scene.shapes[1].material.absorption, Rgb());
    EXPECT_EQ(scene.shapes[2].material.absorption, Rgb());
    EXPECT_EQ(scene.shapes[3].material.absorption, Rgb(kOpaqueAbsorption));
    EXPECT_EQ(scene.shapes[3].material.emission, Rgb(2.0f));
    const Material& lamp = scene.shapes[4].material;
    EXPECT_EQ(lamp.absorption, Rgb(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(lamp.emission, Rgb(1.0f, 0.5f, 0.0f));
    EXPECT_EQ(lamp.intensity, 4.0f);
    EXPECT_EQ(lamp.scaledEmission(), Rgb(4.0f, 2.0f, 0.0f));
    EXPECT_EQ(scene.shapes[4].name, "lamp");
}

TEST(Scene2DJson, IntegralFloatCanvasIsAccepted) {
    EXPECT_EQ(parseOk(R"({"canvas": [64.0, 32]})").width, 64);
}

TEST(Scene2DJson, AlbedoForShapesAndBackground) {
    const Scene2D scene = parseOk(R"({"canvas": [16, 16],
        "background": {"absorption": 0.1, "albedo": [0.5, 0.6, 0.7]},
        "shapes": [{"type": "circle", "center": [8, 8], "radius": 2, "albedo": 0.8}]})");
    EXPECT_EQ(scene.background.albedo, Rgb(0.5f, 0.6f, 0.7f));
    EXPECT_EQ(scene.shapes[0].material.albedo, Rgb(0.8f));
    EXPECT_TRUE(scene.shapes[0].material.isOpaque());
    // Written back and read again unchanged.
    const Scene2D again = parseOk(sceneToJson(scene));
    EXPECT_EQ(again.background.albedo, scene.background.albedo);
    EXPECT_EQ(again.shapes[0].material.albedo, scene.shapes[0].material.albedo);
}

// ---- Errors ---------------------------------------------------------------------------------

// Parses `text` expecting an error on `line` whose message contains `part`.
void expectError(std::string_view text, int line, const std::string& part) {
    Result<Scene2D> scene = parseScene2D(text, "test.json", "");
    ASSERT_FALSE(scene.ok()) << "expected an error containing: " << part;
    const std::string& message = scene.error().message();
    const std::string prefix = "test.json:" + std::to_string(line) + ":";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(Scene2DJsonErrors, FullMessageNamesFileLineColumnAndField) {
    const Result<Scene2D> scene = parseScene2D(R"({"canvas": [10, 10],
  "shapes": [
    {"type": "circle", "center": [1, 2],
     "radius": -4}
  ]
})",
                                               "room.json", "");
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().message(), "room.json:4:16: shapes[0].radius: must be > 0, got -4");
}

TEST(Scene2DJsonErrors, MalformedJson) {
    const Result<Scene2D> scene =
        parseScene2D("{\n  \"canvas\": [1, 2],\n  \"shapes\": [x]\n}", "bad.json", "");
    ASSERT_FALSE(scene.ok());
    const std::string& message = scene.error().message();
    EXPECT_EQ(message.rfind("bad.json:3:14: invalid JSON: syntax error", 0), 0u) << message;
    EXPECT_EQ(message.find("[json.exception"), std::string::npos) << message;
    expectError("{\"canvas\": [1, 2],\n}", 2, "invalid JSON");
    expectError("{\"canvas\": [1, 2]\n", 2, "unexpected end of input");
    expectError("", 1, "invalid JSON");
    expectError("{\"canvas\": [NaN, 2]}", 1, "invalid JSON");
    expectError("{\"canvas\": [1, 2]} {}", 1, "invalid JSON");
}

TEST(Scene2DJsonErrors, NumberOverflowIsNotFinite) {
    expectError("{\"canvas\": [10, 10],\n \"shapes\": [{\"type\": \"circle\", \"radius\": 1e999}]}",
                2, "1e999 is too large (must be finite)");
    const Result<Scene2D> scene = parseScene2D("{\"canvas\": [10, -1e999]}", "t.json", "");
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().message().rfind("t.json:1:17:", 0), 0u) << scene.error().message();
}

TEST(Scene2DJsonErrors, UnknownFields) {
    expectError("{\"canvas\": [10, 10],\n \"shape\": []}", 2,
                "shape: unknown field 'shape' (allowed at the top level: type, description, "
                "canvas, background, boundary_radiance, shapes)");
    expectError(R"({"canvas": [10, 10], "shapes": [
        {"type": "circle", "center": [1, 1],
         "radiuss": 2}]})",
                3,
                "shapes[0].radiuss: unknown field 'radiuss' (allowed for circle: type, name, "
                "comment, center, radius, emission, absorption, opaque, intensity, albedo)");
    expectError(R"({"canvas": [10, 10], "shapes": [
        {"type": "circle", "center": [1, 1], "radius": 1,
         "albedo": [0.5, 1, 0]}]})",
                3, "shapes[0].albedo[1]: must be in [0, 1), got 1");
    expectError("{\"canvas\": [10, 10],\n \"background\": {\"emision\": 1}}", 2,
                "unknown field 'emision'");
    expectError(R"({"canvas": [10, 10], "shapes": [
        {"type": "image", "emission": "a.png", "angle": 3}]})",
                2, "unknown field 'angle' (allowed for image:");
    // Unknown fields point at the key.
    const Result<Scene2D> scene = parseScene2D(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"box\", \"radius\": 1}]}", "t.json", "");
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().message().rfind("t.json:1:49: shapes[0].radius:", 0), 0u)
        << scene.error().message();
}

TEST(Scene2DJsonErrors, UnknownOrMissingType) {
    expectError("{\"canvas\": [10, 10], \"shapes\": [\n  {\"type\": \"triangle\"}]}", 2,
                "shapes[0].type: unknown shape type 'triangle' (known: circle, box, capsule, line, "
                "polygon, image)");
    expectError("{\"canvas\": [10, 10], \"shapes\": [\n  {\"radius\": 1}]}", 2,
                "shapes[0].type: required field is missing");
    expectError("{\"canvas\": [10, 10], \"shapes\": [\n  {\"type\": 3}]}", 2,
                "shapes[0].type: must be a string, got number");
}

TEST(Scene2DJsonErrors, MissingRequiredFields) {
    expectError("{\"shapes\": []}", 1, "canvas: required field is missing");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [\n  {\"type\": \"circle\", \"center\": [1, 1]}]}", 2,
        "shapes[0].radius: required field is missing");
    expectError("{\"canvas\": [10, 10], \"shapes\": [\n  {\"type\": \"box\", \"center\": [1, 1]}]}",
                2, "shapes[0].size: required field is missing");
    expectError("{\"canvas\": [10, 10], \"shapes\": [\n  {\"type\": \"box\", \"min\": [1, 1]}]}", 2,
                "shapes[0].max: required field is missing");
    expectError("{\"canvas\": [10, 10], \"shapes\": [\n  {\"type\": \"line\", \"from\": [1, 1]}]}",
                2, "shapes[0].to: required field is missing");
    expectError("{\"canvas\": [10, 10], \"shapes\": [\n  {\"type\": \"polygon\"}]}", 2,
                "shapes[0].points: required field is missing");
}

TEST(Scene2DJsonErrors, WrongJsonTypes) {
    expectError("[1, 2]", 1, "a scene must be a JSON object, got an array of 2 elements");
    expectError("{\"canvas\": [10, 10],\n \"shapes\": {}}", 2,
                "shapes: must be an array, got object");
    expectError("{\"canvas\": [10, 10], \"shapes\": [\n  3]}", 2,
                "shapes[0]: must be an object, got number");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"circle\",\n \"center\": [0, 0], "
        "\"radius\": \"2\"}]}",
        2, "shapes[0].radius: must be a number, got string");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"circle\", \"radius\": 2,\n"
        "  \"center\": [1, true]}]}",
        2, "shapes[0].center[1]: must be a number, got boolean");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"circle\", \"radius\": 2,\n"
        "  \"center\": [1, 1], \"opaque\": 1}]}",
        2, "shapes[0].opaque: must be true or false, got number");
    expectError("{\"canvas\": [10, 10],\n \"description\": 5}", 2,
                "description: must be a string, got number");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"circle\", \"radius\": 2,\n"
        "  \"center\": [1, 1], \"name\": null}]}",
        2, "shapes[0].name: must be a string, got null");
    expectError("{\"canvas\": [10, 10],\n \"background\": [1]}", 2,
                "background: must be an object, got an array of 1 element");
}

TEST(Scene2DJsonErrors, WrongArrayLengths) {
    expectError("{\"canvas\":\n [10]}", 2, "canvas: must be [width, height], got an array of 1");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"circle\", \"radius\": 2,\n"
        "  \"center\": [1, 2, 3]}]}",
        2, "shapes[0].center: must be [x, y], got an array of 3 elements");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"box\", \"center\": [1, 2],\n"
        "  \"size\": 4}]}",
        2, "shapes[0].size: must be [width, height], got number");
    expectError("{\"canvas\": [10, 10],\n \"boundary_radiance\": [1, 2]}", 2,
                "boundary_radiance: must be [r, g, b] or one number, got an array of 2 elements");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"polygon\",\n"
        "  \"points\": [[0, 0], [1, 0]]}]}",
        2, "shapes[0].points: must have at least 3 points, got 2");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"polygon\", \"points\":\n"
        "  [[0, 0], [1, 0],\n  [1]]}]}",
        3, "shapes[0].points[2]: must be [x, y], got an array of 1 element");
}

TEST(Scene2DJsonErrors, NumberRanges) {
    const std::string head = "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"circle\",\n";
    expectError(head + "  \"center\": [2e6, 0], \"radius\": 1}]}", 2,
                "shapes[0].center[0]: must be within [-1e6, 1e6], got 2000000");
    expectError(head + "  \"center\": [0, 0], \"radius\": 0}]}", 2,
                "shapes[0].radius: must be > 0, got 0");
    expectError(head + "  \"center\": [0, 0], \"radius\": 1e7}]}", 2,
                "shapes[0].radius: must be <= 1e6, got 10000000");
    expectError(head + "  \"center\": [0, 0], \"radius\": 1, \"emission\": -1}]}", 2,
                "shapes[0].emission: must be >= 0, got -1");
    expectError(head + "  \"center\": [0, 0], \"radius\": 1, \"emission\": [1, -0.5, 1]}]}", 2,
                "shapes[0].emission[1]: must be >= 0, got -0.5");
    expectError(head + "  \"center\": [0, 0], \"radius\": 1, \"absorption\": -2}]}", 2,
                "shapes[0].absorption: must be >= 0, got -2");
    expectError(head + "  \"center\": [0, 0], \"radius\": 1, \"intensity\": -1}]}", 2,
                "shapes[0].intensity: must be >= 0, got -1");
    expectError(head + "  \"center\": [0, 0], \"radius\": 1, \"emission\": 1e300}]}", 2,
                "shapes[0].emission: must be <= 1e30");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"capsule\", \"from\": [0, 0],\n"
        "  \"to\": [1, 1], \"thickness\": -1}]}",
        2, "shapes[0].thickness: must be > 0, got -1");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"box\", \"center\": [0, 0],\n"
        "  \"size\": [1, 0]}]}",
        2, "shapes[0].size[1]: must be > 0, got 0");
    expectError("{\"canvas\": [10, 10],\n \"background\": {\"absorption\": [0, 0, -1]}}", 2,
                "background.absorption[2]: must be >= 0, got -1");
}

TEST(Scene2DJsonErrors, CanvasSize) {
    expectError("{\"canvas\": [10,\n 100000]}", 2,
                "canvas[1]: absurd canvas size 100000 (at most 65536)");
    expectError("{\"canvas\": [\n0, 10]}", 2, "canvas[0]: must be >= 1, got 0");
    expectError("{\"canvas\": [\n-5, 10]}", 2, "canvas[0]: must be >= 1, got -5");
    expectError("{\"canvas\": [10,\n 10.5]}", 2, "canvas[1]: must be a whole number, got 10.5");
    expectError("{\"canvas\": [10,\n \"10\"]}", 2, "canvas[1]: must be a number, got string");
}

TEST(Scene2DJsonErrors, BoxForms) {
    const std::string head = "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"box\",\n";
    expectError(head + "  \"min\": [0, 0], \"max\": [1, 1], \"angle\": 30}]}", 2,
                "shapes[0].angle: cannot be combined with min/max");
    expectError(head + "  \"min\": [0, 0], \"max\": [1, 1],\n  \"center\": [1, 1]}]}", 3,
                "shapes[0].center: cannot be combined with min/max");
    expectError(head + "  \"min\": [0, 5],\n  \"max\": [1, 5]}]}", 3,
                "shapes[0].max: must be greater than min in x and y, got min [0, 5], max [1, 5]");
    expectError(head + "  \"center\": [0, 0], \"size\": [1, 1],\n  \"angle\": \"30\"}]}", 3,
                "shapes[0].angle: must be a number, got string");
}

TEST(Scene2DJsonErrors, OpaqueAndAbsorptionConflict) {
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"circle\", \"center\": [0, 0],\n"
        "  \"radius\": 1, \"opaque\": true,\n  \"absorption\": 1}]}",
        3, "shapes[0].absorption: cannot be combined with \"opaque\": true");
}

TEST(Scene2DJsonErrors, ImageLayerFields) {
    expectError("{\"canvas\": [10, 10], \"shapes\": [\n  {\"type\": \"image\"}]}", 2,
                "shapes[0]: an image layer needs \"emission\" and/or \"absorption\"");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"image\", \"emission\": \"a.png\",\n"
        "  \"opaque\": true}]}",
        2, "shapes[0].opaque: is not allowed for image layers");
    expectError("{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"image\",\n  \"emission\": 1}]}",
                2, "shapes[0].emission: must be the path of a PNG file, got number");
    expectError(
        "{\"canvas\": [10, 10], \"shapes\": [{\"type\": \"image\", \"emission\": \"a.png\",\n"
        "  \"absorption_scale\": -1}]}",
        2, "shapes[0].absorption_scale: must be >= 0, got -1");
}

// ---- Files and images -----------------------------------------------------------------------

// A fresh folder per test (TempDirTest) for scene files and their pictures.
class Scene2DFiles : public test::TempDirTest {
  protected:
    // A 2x1 RGBA picture: opaque red, then half-transparent grey.
    std::string writeTestPng(const std::string& name) {
        Image image(2, 1, 4);
        image.at(0, 0, 0) = 1.0f;
        image.at(0, 0, 3) = 1.0f;
        image.setRgb(1, 0, Rgb(0.5f));
        image.at(1, 0, 3) = 0.5f;
        const fs::path path = dir() / name;
        fs::create_directories(path.parent_path());
        const Status status = writePng(path.string(), image, PngEncoding::Srgb);
        EXPECT_TRUE(status.ok()) << status.error().message();
        return path.string();
    }
};

TEST_F(Scene2DFiles, MissingFile) {
    const std::string path = (dir() / "nope.json").string();
    const Result<Scene2D> scene = loadScene2D(path);
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().message(),
              "cannot open scene '" + path + "': No such file or directory");
}

TEST_F(Scene2DFiles, DirectoryIsNotAScene) {
    const Result<Scene2D> scene = loadScene2D(dir().string());
    ASSERT_FALSE(scene.ok());
    EXPECT_NE(scene.error().message().find("Is a directory"), std::string::npos)
        << scene.error().message();
}

TEST_F(Scene2DFiles, RefusesHugeFiles) {
    // A sparse file: the size check must come before reading it.
    const std::string path = write("huge.json", "");
    fs::resize_file(path, (std::uintmax_t{64} << 20) + 1);
    const Result<Scene2D> scene = loadScene2D(path);
    ASSERT_FALSE(scene.ok());
    EXPECT_NE(scene.error().message().find("too large"), std::string::npos)
        << scene.error().message();
}

TEST_F(Scene2DFiles, LoadsFromDiskWithFileNameInErrors) {
    const std::string good = write("good.json", R"({"canvas": [4, 3]})");
    const Result<Scene2D> scene = loadScene2D(good);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->width, 4);
    EXPECT_EQ(scene->sourcePath, good);
    const std::string bad = write("bad.json", "{\"canvas\": [4, 3],\n\"shapes\": [{\"type\": 1}]}");
    const Result<Scene2D> failed = loadScene2D(bad);
    ASSERT_FALSE(failed.ok());
    EXPECT_EQ(failed.error().message(),
              bad + ":2:21: shapes[0].type: must be a string, got number");
}

TEST_F(Scene2DFiles, ImageLayerLoadsRelativeToTheSceneFile) {
    writeTestPng("pics/glow.png");
    writeTestPng("pics/walls.png");
    const std::string path = write("scene.json", R"({"canvas": [40, 30], "shapes": [
        {"type": "image", "emission": "pics/glow.png", "intensity": 3},
        {"type": "image", "absorption": "pics/walls.png", "position": [5, 6], "size": [10, 20],
         "absorption_scale": 0.5, "name": "walls"}
    ]})");
    const Result<Scene2D> scene = loadScene2D(path);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    ASSERT_EQ(scene->shapes.size(), 2u);

    const auto& glow = std::get<ImageLayer>(scene->shapes[0].geometry);
    EXPECT_EQ(glow.position, (Vec2d{0, 0}));
    EXPECT_EQ(glow.size, (Vec2d{40, 30}));  // defaults to the canvas
    ASSERT_NE(glow.emission, nullptr);
    EXPECT_EQ(glow.absorption, nullptr);
    EXPECT_EQ(glow.emissionPath, "pics/glow.png");
    EXPECT_EQ(glow.emission->width(), 2);
    EXPECT_EQ(glow.emission->channels(), 4);
    EXPECT_NEAR(glow.emission->at(0, 0, 0), 1.0f, 1e-6f);
    EXPECT_NEAR(glow.emission->at(1, 0, 0), 0.5f, 0.01f);  // sRGB decoded back to linear
    EXPECT_NEAR(glow.emission->at(1, 0, 3), 0.5f, 0.01f);
    EXPECT_EQ(glow.absorptionScale, 1.0f);
    EXPECT_EQ(scene->shapes[0].material.intensity, 3.0f);
    EXPECT_STREQ(geometryTypeName(scene->shapes[0].geometry), "image");

    const auto& walls = std::get<ImageLayer>(scene->shapes[1].geometry);
    EXPECT_EQ(walls.position, (Vec2d{5, 6}));
    EXPECT_EQ(walls.size, (Vec2d{10, 20}));
    ASSERT_NE(walls.absorption, nullptr);
    EXPECT_EQ(walls.emission, nullptr);
    EXPECT_EQ(walls.absorptionScale, 0.5f);
    // Read as linear data: the written sRGB value for 0.5 is about 0.735 (188/255).
    EXPECT_NEAR(walls.absorption->at(1, 0, 0), 188.0f / 255.0f, 0.01f);
    EXPECT_EQ(scene->shapes[1].name, "walls");
}

TEST_F(Scene2DFiles, MissingOrCorruptImageNamesFieldAndPath) {
    write("broken.png", "this is not a png");
    const std::string head = "{\"canvas\": [10, 10], \"shapes\": [\n  {\"type\": \"image\",\n";
    Result<Scene2D> missing =
        parseScene2D(head + "   \"emission\": \"missing.png\"}]}", "s.json", dir().string());
    ASSERT_FALSE(missing.ok());
    const std::string& m1 = missing.error().message();
    EXPECT_EQ(m1.rfind("s.json:3:16: shapes[0].emission: cannot load image 'missing.png'", 0), 0u)
        << m1;
    EXPECT_NE(m1.find((dir() / "missing.png").string()), std::string::npos) << m1;
    EXPECT_NE(m1.find("No such file or directory"), std::string::npos) << m1;

    Result<Scene2D> corrupt =
        parseScene2D(head + "   \"absorption\": \"broken.png\"}]}", "s.json", dir().string());
    ASSERT_FALSE(corrupt.ok());
    const std::string& m2 = corrupt.error().message();
    EXPECT_EQ(m2.rfind("s.json:3:18: shapes[0].absorption: cannot load image 'broken.png'", 0), 0u)
        << m2;
    EXPECT_NE(m2.find("not a PNG"), std::string::npos) << m2;
}

// ---- Round trip -----------------------------------------------------------------------------

void expectSameMaterial(const Material& a, const Material& b) {
    EXPECT_EQ(a.emission, b.emission);
    EXPECT_EQ(a.absorption, b.absorption);
    EXPECT_EQ(a.intensity, b.intensity);
}

void expectSameScene(const Scene2D& a, const Scene2D& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.background.emission, b.background.emission);
    EXPECT_EQ(a.background.absorption, b.background.absorption);
    EXPECT_EQ(a.boundaryRadiance, b.boundaryRadiance);
    EXPECT_EQ(a.sourcePath, b.sourcePath);
    ASSERT_EQ(a.shapes.size(), b.shapes.size());
    for (std::size_t i = 0; i < a.shapes.size(); ++i) {
        SCOPED_TRACE("shape " + std::to_string(i));
        const Shape& sa = a.shapes[i];
        const Shape& sb = b.shapes[i];
        EXPECT_EQ(sa.name, sb.name);
        expectSameMaterial(sa.material, sb.material);
        ASSERT_EQ(sa.geometry.index(), sb.geometry.index());
        if (const auto* c = std::get_if<Circle>(&sa.geometry)) {
            const auto& d = std::get<Circle>(sb.geometry);
            EXPECT_EQ(c->center, d.center);
            EXPECT_EQ(c->radius, d.radius);
        } else if (const auto* box = std::get_if<Box>(&sa.geometry)) {
            const auto& other = std::get<Box>(sb.geometry);
            EXPECT_EQ(box->center, other.center);
            EXPECT_EQ(box->size, other.size);
            EXPECT_EQ(box->angleDegrees, other.angleDegrees);
        } else if (const auto* cap = std::get_if<Capsule>(&sa.geometry)) {
            const auto& other = std::get<Capsule>(sb.geometry);
            EXPECT_EQ(cap->from, other.from);
            EXPECT_EQ(cap->to, other.to);
            EXPECT_EQ(cap->thickness, other.thickness);
        } else if (const auto* poly = std::get_if<Polygon>(&sa.geometry)) {
            EXPECT_EQ(poly->points, std::get<Polygon>(sb.geometry).points);
        } else {
            const auto& ia = std::get<ImageLayer>(sa.geometry);
            const auto& ib = std::get<ImageLayer>(sb.geometry);
            EXPECT_EQ(ia.position, ib.position);
            EXPECT_EQ(ia.size, ib.size);
            EXPECT_EQ(ia.absorptionScale, ib.absorptionScale);
            EXPECT_EQ(ia.emissionPath, ib.emissionPath);
            EXPECT_EQ(ia.absorptionPath, ib.absorptionPath);
            ASSERT_EQ(ia.emission == nullptr, ib.emission == nullptr);
            ASSERT_EQ(ia.absorption == nullptr, ib.absorption == nullptr);
            EXPECT_TRUE(!ia.emission || *ia.emission == *ib.emission);
            EXPECT_TRUE(!ia.absorption || *ia.absorption == *ib.absorption);
        }
    }
}

TEST(Scene2DJsonRoundTrip, EveryGeometricShapeAndMaterial) {
    Scene2D scene;
    scene.width = 320;
    scene.height = 200;
    scene.background = {Rgb(0.1f, 0.2f, 0.3f), Rgb(0.001f)};
    scene.boundaryRadiance = Rgb(0.7f, 0.3f, 1e-7f);
    scene.sourcePath = "rt.json";
    auto add = [&](std::string name, Geometry geometry, Material material) {
        scene.shapes.push_back({std::move(name), std::move(geometry), material});
    };
    add("shapes[0]", Circle{{10.25, -3.1}, 0.3}, {Rgb(1, 2, 3), Rgb(kOpaqueAbsorption), 1.0f});
    add("lamp \"quoted\" \xC3\xA9", Box{{50, 60}, {20.5, 1e-3}, -33.3}, {Rgb(0.1f), Rgb(), 2.5f});
    add("shapes[2]", Box{{1e6, -1e6}, {1e6, 0.1}, 0}, {Rgb(), Rgb(0.3f, 0.0f, 7.0f), 0.0f});
    add("beam", Capsule{{0, 0}, {100.5, 50.25}, 3.75}, {Rgb(4.0f), Rgb(0.05f), 1.0f / 3.0f});
    add("shapes[1]", Polygon{{{0, 0}, {10, 0}, {5, 8.125}, {1.0 / 3.0, 2.0 / 7.0}}},
        {Rgb(), Rgb(kOpaqueAbsorption), 1.0f});
    const std::string text = sceneToJson(scene);
    const Result<Scene2D> back = parseScene2D(text, "rt.json", "");
    ASSERT_TRUE(back.ok()) << back.error().message() << "\n" << text;
    expectSameScene(scene, *back);
    EXPECT_EQ(sceneToJson(*back), text);
    // Readable output: 2-space indent, type first, opaque shapes written as "opaque": true.
    EXPECT_NE(text.find("{\n  \"canvas\": [320, 200],\n"), std::string::npos) << text;
    EXPECT_NE(text.find("{\n      \"type\": \"circle\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"opaque\": true"), std::string::npos) << text;
    EXPECT_NE(text.find("\"absorption\": 0.001"), std::string::npos) << text;
}

TEST(Scene2DJsonRoundTrip, EmptyScene) {
    Scene2D scene;
    scene.width = 1;
    scene.height = 1;
    const Result<Scene2D> back = parseScene2D(sceneToJson(scene), "", "");
    ASSERT_TRUE(back.ok()) << back.error().message();
    expectSameScene(scene, *back);
}

TEST_F(Scene2DFiles, ImageLayerRoundTrip) {
    writeTestPng("glow.png");
    writeTestPng("sub/walls.png");
    const std::string text = R"({"canvas": [16, 8], "shapes": [
        {"type": "circle", "center": [3, 3], "radius": 2, "absorption": 0},
        {"type": "image", "emission": "glow.png", "absorption": "sub/walls.png",
         "position": [-2, 1.5], "size": [4, 2], "absorption_scale": 8, "intensity": 0.25},
        {"type": "image", "emission": "glow.png"}
    ]})";
    const Result<Scene2D> scene = parseScene2D(text, "img.json", dir().string());
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const std::string written = sceneToJson(*scene);
    const Result<Scene2D> back = parseScene2D(written, "img.json", dir().string());
    ASSERT_TRUE(back.ok()) << back.error().message() << "\n" << written;
    expectSameScene(*scene, *back);
    EXPECT_NE(written.find("\"emission\": \"glow.png\""), std::string::npos) << written;
    EXPECT_NE(written.find("\"absorption\": \"sub/walls.png\""), std::string::npos) << written;
}

}  // namespace
}  // namespace luxel::gi2d
