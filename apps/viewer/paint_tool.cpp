// Brush strokes -> capsule shapes.
#include "paint_tool.h"

#include <cmath>
#include <string>

namespace luxel::viewer {
namespace {

void addSegment(gi2d::Scene2D& scene, const Brush& brush, Vec2d from, Vec2d to, int stroke) {
    gi2d::Shape shape;
    shape.name = std::string("paint-") + brushKindName(brush.kind) + "-" + std::to_string(stroke);
    shape.geometry = gi2d::Capsule{from, to, brush.size};
    shape.material = brushMaterial(brush, scene);
    scene.shapes.push_back(std::move(shape));
}

double distance(Vec2d a, Vec2d b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

}  // namespace

const char* brushKindName(BrushKind kind) {
    switch (kind) {
        case BrushKind::Wall:
            return "wall";
        case BrushKind::Emitter:
            return "emitter";
        case BrushKind::Medium:
            return "medium";
        case BrushKind::Eraser:
            return "eraser";
    }
    return "?";
}

gi2d::Material brushMaterial(const Brush& brush, const gi2d::Scene2D& scene) {
    gi2d::Material m;
    switch (brush.kind) {
        case BrushKind::Wall:
            m.absorption = Rgb(gi2d::kOpaqueAbsorption);
            break;
        case BrushKind::Emitter:
            m.absorption = Rgb(gi2d::kOpaqueAbsorption);
            m.emission = brush.emission;
            m.intensity = brush.intensity;
            break;
        case BrushKind::Medium:
            m.absorption = brush.absorption;
            m.emission = brush.emission;
            m.intensity = brush.intensity;
            break;
        case BrushKind::Eraser:
            m.absorption = scene.background.absorption;
            m.emission = scene.background.emission;
            break;
    }
    return m;
}

void PaintTool::begin(gi2d::Scene2D& scene, const Brush& brush, Vec2d point) {
    ++strokeIndex_;
    strokeStarts_.push_back(scene.shapes.size());
    addSegment(scene, brush, point, point, strokeIndex_);
    last_ = point;
}

bool PaintTool::extend(gi2d::Scene2D& scene, const Brush& brush, Vec2d point) {
    if (!last_) return false;
    if (distance(*last_, point) < std::max(brush.size * 0.25, 1.0)) return false;
    addSegment(scene, brush, *last_, point, strokeIndex_);
    last_ = point;
    return true;
}

bool PaintTool::end(gi2d::Scene2D& scene, const Brush& brush, Vec2d point) {
    if (!last_) return false;
    const bool changed = distance(*last_, point) > 0.5;
    if (changed) addSegment(scene, brush, *last_, point, strokeIndex_);
    last_.reset();
    return changed;
}

bool PaintTool::undo(gi2d::Scene2D& scene) {
    if (active() || strokeStarts_.empty()) return false;
    const std::size_t start = strokeStarts_.back();
    strokeStarts_.pop_back();
    if (start > scene.shapes.size()) return false;  // the scene was replaced meanwhile
    scene.shapes.resize(start);
    return true;
}

}  // namespace luxel::viewer
