// Test helper: the shipped 2D scenes, rasterised at a chosen size.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/scene2d_json.h"

namespace luxel::gi2d::testing_support {

inline Medium2D shippedScene(const std::string& name, int width, int height) {
    auto scene = loadScene2D(std::string(LUXEL_SOURCE_DIR) + "/scenes/2d/" + name);
    EXPECT_TRUE(scene.ok()) << scene.error().message();
    auto medium = rasterize(*scene, {width, height, 16});
    EXPECT_TRUE(medium.ok()) << medium.error().message();
    return std::move(medium).value();
}

// "many-lights.json" -> "many_lights", for parameterised test names.
inline std::string sceneTestName(const std::string& file) {
    std::string n = file.substr(0, file.find('.'));
    for (char& c : n) c = c == '-' ? '_' : c;
    return n;
}

}  // namespace luxel::gi2d::testing_support
