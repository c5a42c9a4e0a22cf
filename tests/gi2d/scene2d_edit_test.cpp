// Picking and moving shapes (the viewer's drag and light keys).
#include <gtest/gtest.h>

#include "luxel/gi2d/scene2d_edit.h"

namespace luxel::gi2d {
namespace {

Scene2D twoShapes() {
    Scene2D scene;
    scene.width = scene.height = 100;
    Shape box{"box", Box{{50, 50}, {40, 40}, 0}, {Rgb(0), Rgb(kOpaqueAbsorption), 1}};
    Shape disk{"disk", Circle{{60, 50}, 10}, {Rgb(1, 1, 1), Rgb(kOpaqueAbsorption), 3}};
    scene.shapes = {box, disk};
    return scene;
}

TEST(Scene2DEdit, PickReturnsTheTopmostShapeUnderThePoint) {
    const Scene2D scene = twoShapes();
    EXPECT_EQ(pickShape(scene, {60, 50}), 1);  // both contain it; the disk is drawn later
    EXPECT_EQ(pickShape(scene, {35, 50}), 0);
    EXPECT_EQ(pickShape(scene, {5, 5}), -1);
    // Just outside the box's edge (x = 30): only with a tolerance.
    EXPECT_EQ(pickShape(scene, {28.5, 50}), -1);
    EXPECT_EQ(pickShape(scene, {28.5, 50}, 2.0), 0);
}

TEST(Scene2DEdit, TranslateMovesEveryGeometryType) {
    const Vec2d d{5, -3};
    Shape circle{"", Circle{{10, 10}, 2}, {}};
    Shape capsule{"", Capsule{{0, 0}, {4, 0}, 1}, {}};
    Shape polygon{"", Polygon{{{0, 0}, {4, 0}, {0, 4}}}, {}};
    ImageLayer layer;
    layer.position = {1, 1};
    layer.size = {2, 2};
    Shape image{"", layer, {}};
    for (Shape* s : {&circle, &capsule, &polygon, &image}) {
        const Vec2d before = shapeCenter(*s);
        translateShape(*s, d);
        const Vec2d after = shapeCenter(*s);
        EXPECT_NEAR(after.x - before.x, d.x, 1e-9) << geometryTypeName(s->geometry);
        EXPECT_NEAR(after.y - before.y, d.y, 1e-9) << geometryTypeName(s->geometry);
    }
}

TEST(Scene2DEdit, BrightestEmitterIsTheLight) {
    Scene2D scene = twoShapes();
    EXPECT_EQ(brightestEmitter(scene), 1);
    scene.shapes[1].material.intensity = 0;
    EXPECT_EQ(brightestEmitter(scene), -1);
}

}  // namespace
}  // namespace luxel::gi2d
