// 2D mode: input -> scene and view edits -> State2D posts; panel controls.
#include "mode_2d.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "luxel/core/file_io.h"
#include "luxel/gi2d/scene2d_edit.h"
#include "luxel/gi2d/scene2d_json.h"

namespace luxel::viewer {
namespace {

// The raylib radiance-cascades demo's 1-5 keys: red, green, blue, yellow, white.
constexpr Rgb kLightColours[5] = {
    {1.0f, 0.15f, 0.1f}, {0.15f, 1.0f, 0.2f}, {0.15f, 0.3f, 1.0f}, {1.0f, 0.9f, 0.2f}, {1, 1, 1}};

// What the G key cycles through and the panel offers: each solver, RC with both merges.
struct SolverSetting {
    gi2d::Solver2D solver;
    gi2d::RcMerge merge;
    const char* label;
};
constexpr SolverSetting kSolvers[] = {
    {gi2d::Solver2D::Hrc, gi2d::RcMerge::Vanilla, "HRC"},
    {gi2d::Solver2D::Rc, gi2d::RcMerge::Vanilla, "RC vanilla"},
    {gi2d::Solver2D::Rc, gi2d::RcMerge::BilinearFix, "RC bilinear fix"},
    {gi2d::Solver2D::Reference, gi2d::RcMerge::Vanilla, "reference"},
};
constexpr int kSolverCount = static_cast<int>(std::size(kSolvers));

int solverIndex(const View2D& view) {
    for (int i = 0; i < kSolverCount; ++i) {
        const SolverSetting& s = kSolvers[i];
        if (s.solver == view.solver && (s.solver != gi2d::Solver2D::Rc || s.merge == view.merge))
            return i;
    }
    return 0;
}

void chooseSolver(View2D& view, int index) {
    view.solver = kSolvers[index].solver;
    if (view.solver == gi2d::Solver2D::Rc) view.merge = kSolvers[index].merge;
    view.cascade = -1;
}

constexpr gpu::Backend kBackends[] = {gpu::Backend::Auto, gpu::Backend::Cpu, gpu::Backend::Gpu};
constexpr const char* kBackendLabels[] = {"auto", "cpu", "gpu"};

int backendIndex(gpu::Backend backend) {
    return static_cast<int>(std::find(std::begin(kBackends), std::end(kBackends), backend) -
                            std::begin(kBackends));
}

}  // namespace

Mode2D::Mode2D(gi2d::Scene2D scene, Mode2DSettings settings)
    : scene_(std::move(scene)),
      view_(settings.view),
      savePath_(std::move(settings.savePath)),
      lightIndex_(gi2d::brightestEmitter(scene_)),
      worker_(std::make_unique<Renderer2D>()) {}

gi2d::Shape* Mode2D::light() {
    if (lightIndex_ < 0 || lightIndex_ >= static_cast<int>(scene_.shapes.size())) return nullptr;
    return &scene_.shapes[static_cast<std::size_t>(lightIndex_)];
}

Vec2d Mode2D::toScene(double wx, double wy, const ViewRect& view) const {
    const Vec2d u = view.toUnit(wx, wy);
    return {u.x * scene_.width, u.y * scene_.height};
}

void Mode2D::handleKey(const SDL_KeyboardEvent& key) {
    const SDL_Keycode k = key.keysym.sym;
    const bool ctrl = (key.keysym.mod & KMOD_CTRL) != 0;
    if (ctrl && k == SDLK_s) {
        (void)save();
        return;
    }
    if (ctrl && k == SDLK_z) {
        if (paint_.undo(scene_)) sceneChanged();
        return;
    }
    gi2d::Shape* lit = light();
    switch (k) {
        case SDLK_SPACE:
            view_.probes = !view_.probes;
            break;
        case SDLK_r:
            view_.gi = !view_.gi;
            break;
        case SDLK_c: {
            const int n = cascadeCount(view_);
            view_.cascade = view_.cascade + 1 >= n ? -1 : view_.cascade + 1;
            break;
        }
        case SDLK_UP:
        case SDLK_DOWN:
            if (!lit) return;
            lit->material.intensity *= k == SDLK_UP ? 1.25f : 0.8f;
            sceneChanged();
            return;
        case SDLK_1:
        case SDLK_2:
        case SDLK_3:
        case SDLK_4:
        case SDLK_5:
            if (!lit) return;
            lit->material.emission = kLightColours[k - SDLK_1];
            sceneChanged();
            return;
        case SDLK_g:
            chooseSolver(view_, (solverIndex(view_) + 1) % kSolverCount);
            break;
        case SDLK_b:
            view_.backend = kBackends[(backendIndex(view_.backend) + 1) % 3];
            break;
        case SDLK_LEFTBRACKET:
            view_.exposure -= 0.5f;
            break;
        case SDLK_RIGHTBRACKET:
            view_.exposure += 0.5f;
            break;
        case SDLK_p:
            paintMode_ = !paintMode_;
            panelRequest_ = paintMode_;
            return;
        case SDLK_TAB:
            if (paintMode_)
                brush_.kind = static_cast<BrushKind>((static_cast<int>(brush_.kind) + 1) % 4);
            return;
        default:
            return;
    }
    viewChanged();
}

void Mode2D::handleEvent(const SDL_Event& event, const ViewRect& view) {
    lastView_ = view;
    if (event.type == SDL_MOUSEMOTION) pointer_ = {double(event.motion.x), double(event.motion.y)};
    switch (event.type) {
        case SDL_KEYDOWN:
            handleKey(event.key);
            break;
        case SDL_MOUSEBUTTONDOWN: {
            if (event.button.button != SDL_BUTTON_LEFT) break;
            const Vec2d p = toScene(event.button.x, event.button.y, view);
            if (paintMode_) {
                paint_.begin(scene_, brush_, p);
                sceneChanged();
                break;
            }
            dragIndex_ = gi2d::pickShape(scene_, p, /*tolerance=*/2.0);
            if (dragIndex_ < 0 && light()) {
                // Empty space: the light jumps to the pointer, as in the raylib demo.
                dragIndex_ = lightIndex_;
                gi2d::translateShape(*light(), p - gi2d::shapeCenter(*light()));
                sceneChanged();
            }
            if (dragIndex_ >= 0 && scene_.shapes[static_cast<std::size_t>(dragIndex_)]
                                           .material.scaledEmission()
                                           .maxComponent() > 0) {
                lightIndex_ = dragIndex_;  // a grabbed emitter becomes the light keys act on
            }
            dragLast_ = p;
            break;
        }
        case SDL_MOUSEMOTION: {
            const Vec2d p = toScene(event.motion.x, event.motion.y, view);
            if (paint_.active()) {
                if (paint_.extend(scene_, brush_, p)) sceneChanged();
            } else if (dragIndex_ >= 0) {
                gi2d::translateShape(scene_.shapes[static_cast<std::size_t>(dragIndex_)],
                                     p - dragLast_);
                dragLast_ = p;
                sceneChanged();
            }
            break;
        }
        case SDL_MOUSEBUTTONUP: {
            if (event.button.button != SDL_BUTTON_LEFT) break;
            const Vec2d p = toScene(event.button.x, event.button.y, view);
            if (paint_.active()) {
                if (paint_.end(scene_, brush_, p)) sceneChanged();
            } else if (dragIndex_ >= 0) {
                gi2d::translateShape(scene_.shapes[static_cast<std::size_t>(dragIndex_)],
                                     p - dragLast_);
                sceneChanged();
            }
            dragIndex_ = -1;
            break;
        }
        case SDL_MOUSEWHEEL:
            if (paintMode_) {
                brush_.size =
                    std::clamp(brush_.size * (event.wheel.y > 0 ? 1.25 : 0.8), 1.0, 400.0);
            }
            break;
        default:
            break;
    }
}

void Mode2D::update(double) {
    if (!dirty_) return;
    dirty_ = false;
    ++generation_;
    worker_.post({std::make_shared<const gi2d::Scene2D>(scene_), sceneVersion_, view_},
                 generation_);
}

std::shared_ptr<const Frame> Mode2D::latestFrame(bool* fresh) {
    return worker_.latest(fresh);
}

bool Mode2D::frameCurrent() {
    auto frame = worker_.latest();
    return frame && !dirty_ && frame->generation == generation_;
}

bool Mode2D::frameConverged() {
    auto frame = worker_.latest();
    return frameCurrent() && frame->converged;
}

Status Mode2D::save() {
    // Through a temporary and a rename: a failed save keeps the scene file as it was.
    if (Status s = writeFileAtomically(savePath_, gi2d::sceneToJson(scene_), "scene"); !s) {
        saveMessage_ = "could not write " + savePath_;
        std::fprintf(stderr, "luxel-view: error: %s\n", s.error().message().c_str());
        return s;
    }
    saveMessage_ = "saved " + savePath_;
    std::printf("luxel-view: saved %s\n", savePath_.c_str());
    return Ok{};
}

void Mode2D::drawStats() {
    if (!paintMode_) return;
    static const char* kinds[] = {"wall", "emitter", "medium", "eraser"};
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
    ImGui::TextWrapped("paint mode: %s brush, %.0f px (Tab, wheel); Ctrl+Z undo, Ctrl+S save",
                       kinds[static_cast<int>(brush_.kind)], brush_.size);
    ImGui::PopStyleColor();
}

void Mode2D::drawOverFrame() {
    // The brush outline under the pointer, so paint mode is visible without the panel.
    if (!paintMode_ || pointer_.x < 0 || scene_.width <= 0) return;
    const double radius = 0.5 * brush_.size * lastView_.width / scene_.width;
    ImGui::GetForegroundDrawList()->AddCircle(
        ImVec2(static_cast<float>(pointer_.x), static_cast<float>(pointer_.y)),
        static_cast<float>(std::max(radius, 2.0)), IM_COL32(255, 204, 77, 220), 0, 1.5f);
}

void Mode2D::drawPanel() {
    int solver = solverIndex(view_);
    const char* solverLabels[kSolverCount];
    for (int i = 0; i < kSolverCount; ++i) solverLabels[i] = kSolvers[i].label;
    if (ImGui::Combo("solver (G)", &solver, solverLabels, kSolverCount)) {
        chooseSolver(view_, solver);
        viewChanged();
    }
    int backend = backendIndex(view_.backend);
    if (ImGui::Combo("backend (B)", &backend, kBackendLabels, 3)) {
        view_.backend = kBackends[backend];
        viewChanged();
    }
    if (ImGui::SliderFloat("exposure ([ ])", &view_.exposure, -6.0f, 6.0f, "%.1f stops")) {
        viewChanged();
    }
    if (ImGui::Checkbox("GI (R)", &view_.gi)) viewChanged();
    ImGui::SameLine();
    if (ImGui::Checkbox("probes (SPACE)", &view_.probes)) viewChanged();
    // Bounce light: one bounce per frame (renderer_2d.h).
    if (ImGui::Checkbox("bounce light", &view_.bounce)) viewChanged();
    ImGui::SameLine();
    if (ImGui::SliderInt("bounces", &view_.bounces, 1, 64)) viewChanged();
    // RC: jittered probe grids averaged over frames (renderer_2d.h).
    if (view_.solver == gi2d::Solver2D::Rc &&
        ImGui::SliderInt("RC probe grids", &view_.rcJitters, 1, 64)) {
        viewChanged();
    }
    // HRC's exact corrections (renderer_2d.h).
    if (view_.solver == gi2d::Solver2D::Hrc) {
        if (ImGui::Checkbox("exact near field", &view_.exactNearField)) viewChanged();
        ImGui::SameLine();
        if (ImGui::Checkbox("exact direct light", &view_.exactDirectLight)) viewChanged();
    }
    const int cascades = cascadeCount(view_);
    if (cascades > 0 && ImGui::SliderInt("cascade (C)", &view_.cascade, -1, cascades - 1,
                                         view_.cascade < 0 ? "fluence" : "cascade %d")) {
        viewChanged();
    }
    if (gi2d::Shape* lit = light()) {
        ImGui::Text("light: %s", lit->name.c_str());
        if (ImGui::SliderFloat("intensity (Up/Down)", &lit->material.intensity, 0.0f, 100.0f,
                               "%.2f", ImGuiSliderFlags_Logarithmic)) {
            sceneChanged();
        }
        if (ImGui::ColorEdit3("colour (1-5)", &lit->material.emission.r)) sceneChanged();
    }
    ImGui::Separator();
    if (ImGui::Checkbox("paint mode (P)", &paintMode_) && paintMode_) panelRequest_ = true;
    if (paintMode_) {
        int kind = static_cast<int>(brush_.kind);
        const char* kinds[] = {"wall", "emitter", "medium", "eraser"};
        if (ImGui::Combo("brush (Tab)", &kind, kinds, 4))
            brush_.kind = static_cast<BrushKind>(kind);
        float size = static_cast<float>(brush_.size);
        if (ImGui::SliderFloat("size (wheel)", &size, 1.0f, 200.0f, "%.0f px")) brush_.size = size;
        if (brush_.kind == BrushKind::Emitter || brush_.kind == BrushKind::Medium) {
            ImGui::ColorEdit3("emission", &brush_.emission.r);
            ImGui::SliderFloat("brush intensity", &brush_.intensity, 0.0f, 50.0f, "%.2f",
                               ImGuiSliderFlags_Logarithmic);
        }
        if (brush_.kind == BrushKind::Medium) {
            ImGui::SliderFloat3("absorption", &brush_.absorption.r, 0.0f, 2.0f, "%.3f",
                                ImGuiSliderFlags_Logarithmic);
        }
        if (ImGui::Button("undo (Ctrl+Z)") && paint_.undo(scene_)) sceneChanged();
        ImGui::SameLine();
        if (ImGui::Button("save (Ctrl+S)")) (void)save();
        ImGui::SameLine();
        ImGui::TextUnformatted(savePath_.c_str());
    }
    if (!saveMessage_.empty()) ImGui::TextUnformatted(saveMessage_.c_str());
}

}  // namespace luxel::viewer
