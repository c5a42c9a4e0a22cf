// Test helper: an opaque emissive disk in vacuum and the pixels where its fluence is known,
// E asin(R' / r) / pi with R' = R + 1/2 (a rasterised edge acts like a disk half a pixel larger,
// docs/conventions.md).
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d::testing_support {

inline constexpr Vec2d kDiskCentre{64, 160};

inline Scene2D analyticDiskScene(double radius, float emission) {
    Scene2D scene{320, 320, {}, {}, {}, ""};
    scene.shapes.push_back(
        {"disk", Circle{kDiskCentre, radius}, Material{Rgb(emission), Rgb(kOpaqueAbsorption)}});
    return scene;
}

struct DiskProbe {
    int x, y;
    double distanceOverRadius;
    double exact;  // expected mean radiance
};

// Pixels to the right of the disk at r / R = 1.5, 2, 3 and 5.
inline std::vector<DiskProbe> diskProbes(double radius, double emission) {
    std::vector<DiskProbe> probes;
    for (double ratio : {1.5, 2.0, 3.0, 5.0}) {
        const int x = static_cast<int>(kDiskCentre.x + ratio * radius);
        const int y = static_cast<int>(kDiskCentre.y);
        const double r = std::hypot(x + 0.5 - kDiskCentre.x, y + 0.5 - kDiskCentre.y);
        probes.push_back(
            {x, y, r / radius, emission * std::asin((radius + 0.5) / r) / std::numbers::pi});
    }
    return probes;
}

}  // namespace luxel::gi2d::testing_support
