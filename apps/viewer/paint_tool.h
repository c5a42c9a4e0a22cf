// Paint mode for 2D scenes: mouse strokes become capsule shapes appended to the Scene2D, so a
// painted scene is an ordinary scene file (saved with sceneToJson, loaded with loadScene2D).
#pragma once

#include <optional>
#include <vector>

#include "luxel/core/vec.h"
#include "luxel/gi2d/scene2d.h"

namespace luxel::viewer {

enum class BrushKind {
    Wall,     // opaque, no emission
    Emitter,  // opaque, emits `emission` x `intensity`
    Medium,   // `absorption` per pixel, emits `emission` x `intensity` (fog, glass, glowing gas)
    Eraser,   // the scene's background medium
};

struct Brush {
    BrushKind kind = BrushKind::Wall;
    double size = 12.0;               // stroke width in scene pixels
    Rgb emission{1.0f, 0.85f, 0.6f};  // Emitter, Medium
    float intensity = 2.0f;
    Rgb absorption{0.05f, 0.05f, 0.05f};  // Medium
};

const char* brushKindName(BrushKind kind);

// The material a brush paints with in `scene` (Eraser reads the background).
gi2d::Material brushMaterial(const Brush& brush, const gi2d::Scene2D& scene);

class PaintTool {
  public:
    // Starts a stroke at `point` (scene pixels): adds a round dab there.
    void begin(gi2d::Scene2D& scene, const Brush& brush, Vec2d point);
    // Extends the stroke; adds a segment once the pointer has moved a quarter of the brush size
    // (fewer, longer capsules keep the scene small). Returns whether the scene changed.
    bool extend(gi2d::Scene2D& scene, const Brush& brush, Vec2d point);
    // Ends the stroke (adds the last bit of the path if it was not added yet).
    bool end(gi2d::Scene2D& scene, const Brush& brush, Vec2d point);
    bool active() const { return last_.has_value(); }
    // Removes the shapes of the last stroke still in the scene; false when there is none.
    bool undo(gi2d::Scene2D& scene);

  private:
    std::optional<Vec2d> last_;
    int strokeIndex_ = 0;
    std::vector<std::size_t> strokeStarts_;  // scene shape count before each stroke
};

}  // namespace luxel::viewer
