// `luxel compare-solvers SCENE --move DX,DY`: how each 2D solver's image changes when the scene's
// brightest light moves by a fraction of a pixel, against how the reference's changes
// (docs/solver-errors.md, "moving lights").
#pragma once

#include <string>

namespace luxel::cli {

struct MovingLightArgs {
    std::string scene, size, move, errorImage;
    int rays = 1024;
    double errorScalePercent = 10;
};

int runCompareMovingLight(const MovingLightArgs& args);

}  // namespace luxel::cli
