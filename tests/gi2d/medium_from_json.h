// A 2D scene's JSON text rasterised at size x size (16 edge samples per pixel side), for tests
// that write their scene inline.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/scene2d_json.h"

namespace luxel::gi2d::testing_support {

inline Medium2D mediumFrom(const std::string& json, int size) {
    auto scene = parseScene2D(json, "test", ".");
    EXPECT_TRUE(scene.ok()) << scene.error().message();
    auto medium = rasterize(*scene, {size, size, 16});
    EXPECT_TRUE(medium.ok()) << medium.error().message();
    return std::move(medium).value();
}

}  // namespace luxel::gi2d::testing_support
