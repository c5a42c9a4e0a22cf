// A program outside luxel's tree, built against an installed luxel (tests/package): a 2D scene
// made in code, solved with HRC on the CPU, checked against the analytic fluence of a disk light.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rasterize.h"

int main() {
    using namespace luxel;
    gi2d::Scene2D scene;
    scene.width = scene.height = 64;
    gi2d::Shape light;
    light.geometry = gi2d::Circle{{32.5, 32.5}, 6.0};
    light.material.emission = Rgb(1.0f);
    light.material.absorption = Rgb(gi2d::kOpaqueAbsorption);
    scene.shapes.push_back(light);
    auto medium = gi2d::rasterize(scene);
    auto fluence = medium ? gi2d::solveHrc(*medium) : Result<Image>(medium.error());
    if (!fluence) {
        std::fprintf(stderr, "luxel consumer: %s\n", fluence.error().message().c_str());
        return 1;
    }
    // 20 px from the centre of a disk of radius 6 and radiance 1: asin(6 / 20) / pi.
    const double expected = std::asin(6.0 / 20.0) / std::numbers::pi;
    const double inside = fluence->at(32, 32, 0), outside = fluence->at(52, 32, 0);
    std::printf("luxel consumer: fluence inside %.4f, at 20 px %.4f (analytic %.4f)\n", inside,
                outside, expected);
    return std::abs(inside - 1.0) < 0.05 && std::abs(outside / expected - 1.0) < 0.1 ? 0 : 1;
}
