// The one JSON toolkit of the scene readers: one wording, located errors, file order.
#include "core/json_fields.h"

#include <gtest/gtest.h>

#include <string>

#include "luxel/gi2d/scene2d_json.h"
#include "luxel/voxel/voxel_scene.h"
#include "support/temp_dir.h"

namespace luxel::json {
namespace {

std::string failure(const char* text, void (*read)(const Json&)) {
    auto root = parse(text, "t.json");
    EXPECT_TRUE(root.ok());
    try {
        read(*root);
    } catch (const Invalid& invalid) {
        return locate(invalid, text, "t.json").message();
    }
    return "";
}

TEST(JsonFields, OneWordingForEveryTypedRead) {
    EXPECT_EQ(failure(R"({"n": 2.5})", [](const Json& r) { readWholeNumber(r["n"], "n", 0, 9); }),
              "t.json:1:7: n: must be a whole number, got 2.5");
    EXPECT_EQ(failure(R"({"n": 12})", [](const Json& r) { readWholeNumber(r["n"], "n", 0, 9); }),
              "t.json:1:7: n: must be in 0..9, got 12");
    EXPECT_EQ(failure(R"({"n": "x"})", [](const Json& r) { readNumber(r["n"], "n"); }),
              "t.json:1:7: n: must be a number, got string");
    EXPECT_EQ(failure(R"({"v": [1, 2]})", [](const Json& r) { readNumbers(r["v"], "v", 3, 0, 9); }),
              "t.json:1:7: v: must be an array of 3 numbers, got an array of 2 elements");
}

TEST(JsonFields, UnknownFieldsAreReportedAtTheirKeyInFileOrder) {
    const char* text = "{\"b\": 1,\n \"zz\": 2,\n \"aa\": 3}";
    EXPECT_EQ(failure(text, [](const Json& r) { checkObject(r, "", {"b"}); }),
              "t.json:2:2: zz: unknown field 'zz' (allowed at the top level: b)");
}

TEST(JsonFields, ParseErrorsAndHugeNumbersAreLocated) {
    auto bad = parse("{\n  \"a\": [1, 2,\n}", "t.json");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message().rfind("t.json:3:1: invalid JSON: ", 0), 0u)
        << bad.error().message();
    auto huge = parse("{\"a\": 1e999}", "t.json");
    ASSERT_FALSE(huge.ok());
    EXPECT_EQ(huge.error().message(),
              "t.json:1:7: invalid JSON: number 1e999 is too large (must be finite)");
}

// Both scene readers go through the toolkit: the same mistake reads the same in both.
TEST(JsonFields, BothSceneReadersUseTheSameWording) {
    auto twoD = gi2d::parseScene2D(R"({"canvas": [10, 10.5]})", "a.json", ".");
    ASSERT_FALSE(twoD.ok());
    EXPECT_NE(twoD.error().message().find("must be a whole number, got 10.5"), std::string::npos)
        << twoD.error().message();
    const test::TempDir tmp;
    const std::string path = tmp.write(
        "voxel.json", R"({"type": "voxel", "world": {"source": "empty", "size": [8, 8, 8]},
        "camera": {"position": [1, 2, 3]}, "render": {"reflections": 1.5}})");
    auto voxel = voxel::loadVoxelScene(path);
    ASSERT_FALSE(voxel.ok());
    EXPECT_NE(voxel.error().message().find("render.reflections: must be a whole number, got 1.5"),
              std::string::npos)
        << voxel.error().message();
}

}  // namespace
}  // namespace luxel::json
