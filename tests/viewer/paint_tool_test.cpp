// Paint mode: strokes become capsules with the brush's material, the painted scene saves as JSON
// that the 2D loader reads back, and the medium shows the paint where it was drawn.
#include <gtest/gtest.h>

#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/scene2d_json.h"
#include "paint_tool.h"

namespace luxel::viewer {
namespace {

gi2d::Scene2D emptyScene() {
    gi2d::Scene2D scene;
    scene.width = 64;
    scene.height = 48;
    scene.background = {Rgb(0.0f), Rgb(0.01f)};
    return scene;
}

TEST(PaintTool, AStrokeAddsCapsulesAlongThePath) {
    gi2d::Scene2D scene = emptyScene();
    PaintTool tool;
    Brush brush;
    brush.size = 4;
    tool.begin(scene, brush, {10, 10});
    EXPECT_TRUE(tool.active());
    EXPECT_FALSE(tool.extend(scene, brush, {10.5, 10}));  // under a quarter of the brush
    EXPECT_TRUE(tool.extend(scene, brush, {20, 10}));
    EXPECT_TRUE(tool.extend(scene, brush, {30, 10}));
    EXPECT_FALSE(tool.end(scene, brush, {30, 10}));  // nothing left to add
    EXPECT_FALSE(tool.active());
    ASSERT_EQ(scene.shapes.size(), 3u);  // the dab and two segments
    const auto& last = std::get<gi2d::Capsule>(scene.shapes.back().geometry);
    EXPECT_EQ(last.from, (Vec2d{20, 10}));
    EXPECT_EQ(last.to, (Vec2d{30, 10}));
    EXPECT_DOUBLE_EQ(last.thickness, 4.0);
    EXPECT_EQ(scene.shapes.back().material.absorption, Rgb(gi2d::kOpaqueAbsorption));
}

TEST(PaintTool, UndoRemovesTheLastStrokeOnly) {
    gi2d::Scene2D scene = emptyScene();
    PaintTool tool;
    Brush brush;
    tool.begin(scene, brush, {10, 10});
    tool.end(scene, brush, {30, 10});
    tool.begin(scene, brush, {10, 30});
    tool.extend(scene, brush, {30, 30});
    tool.end(scene, brush, {40, 30});
    ASSERT_EQ(scene.shapes.size(), 5u);
    EXPECT_TRUE(tool.undo(scene));
    EXPECT_EQ(scene.shapes.size(), 2u);
    EXPECT_TRUE(tool.undo(scene));
    EXPECT_TRUE(scene.shapes.empty());
    EXPECT_FALSE(tool.undo(scene));
}

TEST(PaintTool, BrushMaterials) {
    const gi2d::Scene2D scene = emptyScene();
    Brush brush;
    brush.kind = BrushKind::Emitter;
    brush.emission = {1, 0.5f, 0.25f};
    brush.intensity = 3;
    gi2d::Material m = brushMaterial(brush, scene);
    EXPECT_EQ(m.scaledEmission(), (Rgb{3, 1.5f, 0.75f}));
    EXPECT_EQ(m.absorption, Rgb(gi2d::kOpaqueAbsorption));
    brush.kind = BrushKind::Eraser;
    m = brushMaterial(brush, scene);
    EXPECT_EQ(m.absorption, scene.background.absorption);
    EXPECT_EQ(m.scaledEmission(), scene.background.emission);
}

TEST(PaintTool, PaintedSceneRoundTripsThroughJsonAndShowsInTheMedium) {
    gi2d::Scene2D scene = emptyScene();
    PaintTool tool;
    Brush wall;
    wall.size = 6;
    tool.begin(scene, wall, {8, 24});
    tool.extend(scene, wall, {40, 24});
    tool.end(scene, wall, {40, 24});
    Brush emitter;
    emitter.kind = BrushKind::Emitter;
    emitter.size = 8;
    tool.begin(scene, emitter, {52, 10});
    tool.end(scene, emitter, {52, 10});

    const std::string json = gi2d::sceneToJson(scene);
    auto loaded = gi2d::parseScene2D(json, "painted.json", ".");
    ASSERT_TRUE(loaded) << loaded.error().message();
    EXPECT_EQ(gi2d::sceneToJson(*loaded), json);

    auto medium = gi2d::rasterize(*loaded);
    ASSERT_TRUE(medium) << medium.error().message();
    EXPECT_GT(medium->absorption.at(24, 24, 0), 40.0f);  // on the wall stroke
    EXPECT_LT(medium->absorption.at(24, 40, 0), 0.1f);   // away from it
    EXPECT_GT(medium->emission.at(52, 10, 0), 1.0f);     // the emitter dab
    EXPECT_EQ(medium->emission.at(24, 24, 0), 0.0f);
}

}  // namespace
}  // namespace luxel::viewer
