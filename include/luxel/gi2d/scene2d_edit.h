// Interactive edits of a Scene2D: which shape lies under a point, moving a shape, and which shape
// is "the light" that an interactive program drags by default.
#pragma once

#include "luxel/core/vec.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::gi2d {

// Index of the topmost (last drawn) shape that contains `point` (scene pixels), or -1. A point
// within `tolerance` pixels of a shape's edge counts as inside, so thin lines can be picked.
int pickShape(const Scene2D& scene, Vec2d point, double tolerance = 0.0);

// Centre of the shape's bounding box, in scene pixels.
Vec2d shapeCenter(const Shape& shape);

// Moves a shape by `delta` scene pixels (every geometry type).
void translateShape(Shape& shape, Vec2d delta);

// Index of the shape with the largest emitted luminance (emission x intensity), or -1 when no
// shape emits. Ties go to the later shape (the one drawn on top).
int brightestEmitter(const Scene2D& scene);

}  // namespace luxel::gi2d
