// The 2D scene model: a canvas, a background medium and an ordered list of shapes, each with a
// material (emission radiance + absorption coefficient). Later shapes are drawn over earlier ones
// where they cover (the depth order of the GameMaker HRC demo: far first, near last).
//
// Units: lengths in scene pixels (the canvas size given in the scene), y pointing down, pixel (i,
// j) covering [i, i+1] x [j, j+1]. Absorption sigma is per scene pixel of length. Emission is
// radiance.
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "luxel/core/image.h"
#include "luxel/core/vec.h"

namespace luxel::gi2d {

// Absorption used for "opaque": true. Over one pixel it transmits exp(-50) ~ 2e-22
// (docs/algorithms/pixel-medium.md).
inline constexpr float kOpaqueAbsorption = 50.0f;

// What a shape is made of.
struct Material {
    Rgb emission;    // radiance emitted where the material is optically thick (times intensity)
    Rgb absorption;  // per pixel length; kOpaqueAbsorption when "opaque": true
    float intensity = 1.0f;
    // Fraction of the light arriving that is re-emitted diffusely, per channel, in [0, 1)
    // (docs/algorithms/scattering-2d.md). For an opaque material it is the surface's diffuse
    // reflectance; otherwise the single-scattering albedo of the medium (isotropic scattering).
    Rgb albedo = {};

    Rgb scaledEmission() const { return emission * intensity; }
    bool isOpaque() const { return absorption.minComponent() >= kOpaqueAbsorption; }
};

struct Circle {
    Vec2d center;
    double radius = 0;
};

// A box of the given full size centred at `center`, rotated by `angleDegrees` (clockwise on screen,
// since y points down). angle 0 is an axis-aligned box.
struct Box {
    Vec2d center;
    Vec2d size;
    double angleDegrees = 0;
};

// A line segment swept by a disk: all points within thickness/2 of the segment (round caps).
struct Capsule {
    Vec2d from, to;
    double thickness = 1;
};

// A simple or self-intersecting polygon filled with the even-odd rule.
struct Polygon {
    std::vector<Vec2d> points;
};

// A picture placed on the canvas: emission from an sRGB PNG and/or absorption from a PNG read as
// linear data (value * absorptionScale). Coverage comes from the alpha channel when there is one.
struct ImageLayer {
    Vec2d position;  // top-left corner on the canvas
    Vec2d size;      // extent on the canvas; the images are stretched to it (nearest texel)
    std::shared_ptr<const Image> emission;    // may be null; linear RGB(A)
    std::shared_ptr<const Image> absorption;  // may be null; linear data, channels 0..2 used
    // May be null; linear data in [0, 1), channels 0..2: per-texel albedo (Material::albedo).
    std::shared_ptr<const Image> albedo;
    float absorptionScale = 1.0f;
    std::string emissionPath, absorptionPath, albedoPath;  // as written in the scene
};

using Geometry = std::variant<Circle, Box, Capsule, Polygon, ImageLayer>;

struct Shape {
    std::string name;  // optional label from the scene file (or "shapes[i]")
    Geometry geometry;
    Material material;  // for an ImageLayer: intensity multiplies the emission image
};

struct Medium {
    Rgb emission;
    Rgb absorption;
    Rgb albedo = {};  // single-scattering albedo of the background medium (fog that glows when lit)
};

struct Scene2D {
    int width = 0, height = 0;  // canvas size in pixels
    Medium background;          // fills the canvas before any shape is drawn
    Rgb boundaryRadiance;       // radiance arriving from outside the canvas (0 = dark)
    std::vector<Shape> shapes;  // drawn in order
    std::string sourcePath;     // file it was read from, if any
};

// The type name used in scene files: "circle", "box", "capsule", "polygon", "image".
const char* geometryTypeName(const Geometry& geometry);

// Whether the background, any material or any image layer has a non-zero albedo: light bounces
// in this scene, and its rasterised medium carries scattering / reflectance images.
bool sceneBounces(const Scene2D& scene);

}  // namespace luxel::gi2d
