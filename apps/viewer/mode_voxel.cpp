// Voxel mode input and panel.
#include "mode_voxel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "luxel/voxel/camera.h"
#include "voxel_controls.h"
#include "voxel_solver_panel.h"

namespace luxel::viewer {
namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;
constexpr double kLookDegreesPerPixel = 0.2;
constexpr double kTurnDegrees = 5.0;  // arrow keys

Vec3d forwardOf(const FlyCamera& c) {
    const double yaw = c.yawDegrees * kDegrees, pitch = c.pitchDegrees * kDegrees;
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

Vec3d rightOf(const FlyCamera& c) {
    const double yaw = c.yawDegrees * kDegrees;
    return {std::cos(yaw), 0.0, -std::sin(yaw)};
}

}  // namespace

ModeVoxel::ModeVoxel(voxel::VoxelScene scene, int width, int height, float exposure,
                     std::unique_ptr<VoxelFrameSource> source, std::string savePath,
                     const VoxelSolverOptions& solver)
    : worldSize_(scene.world.size()),
      saver_(scene.world, scene.shading.materials, std::move(savePath)),
      worker_(std::make_unique<RendererVoxel>(std::move(scene.world), std::move(source))) {
    const voxel::Camera& camera = scene.camera;
    const Vec3d f = camera.forward();
    state_.camera.position = camera.position();
    state_.camera.yawDegrees = std::atan2(f.x, f.z) / kDegrees;
    state_.camera.pitchDegrees = std::asin(std::clamp(f.y, -1.0, 1.0)) / kDegrees;
    state_.camera.fovYDegrees = camera.fovYDegrees();
    state_.width = width;
    state_.height = height;
    state_.shading = scene.shading;
    state_.exposure = exposure + scene.post.tone.exposureStops;
    state_.post = scene.post;
    state_.solver = solver;
    const Vec3& s = scene.shading.sunDirection;
    sunLength_ = std::sqrt(double(s.x) * s.x + double(s.y) * s.y + double(s.z) * s.z);
    if (sunLength_ > 0) {
        sunAzimuth_ = std::atan2(s.x, s.z) / kDegrees;
        sunElevation_ = std::asin(std::clamp(s.y / sunLength_, -1.0, 1.0)) / kDegrees;
    }
}

void ModeVoxel::setSun(double azimuthDegrees, double elevationDegrees) {
    sunAzimuth_ = std::fmod(azimuthDegrees + 540.0, 360.0) - 180.0;
    sunElevation_ = std::clamp(elevationDegrees, -10.0, 90.0);
    const double a = sunAzimuth_ * kDegrees, e = sunElevation_ * kDegrees;
    // Same length as the scene's vector: the Unity tracer's face term uses it unnormalised.
    state_.shading.sunDirection = Vec3{static_cast<float>(sunLength_ * std::sin(a) * std::cos(e)),
                                       static_cast<float>(sunLength_ * std::sin(e)),
                                       static_cast<float>(sunLength_ * std::cos(a) * std::cos(e))};
    changed();
}

void ModeVoxel::move(Vec3d direction, double distance) {
    state_.camera.position = state_.camera.position + direction * distance;
    changed();
}

void ModeVoxel::save() {
    if (saver_.save()) {
        std::printf("luxel-view: %s\n", saver_.status().c_str());
    } else {
        std::fprintf(stderr, "luxel-view: %s\n", saver_.status().c_str());
    }
}

void ModeVoxel::handleKey(SDL_Keycode key, bool shift, bool ctrl) {
    // A tap moves one step, so scripted and single presses have a visible, repeatable effect;
    // holding the key keeps moving in update().
    const double step = shift ? 8.0 : 2.0;
    FlyCamera& c = state_.camera;
    voxel::ShadeOptions& s = state_.shading;
    switch (key) {
        case SDLK_w:
            move(forwardOf(c), step);
            break;
        case SDLK_s:
            if (ctrl) {
                save();
                return;
            }
            move(forwardOf(c), -step);
            break;
        case SDLK_d:
            move(rightOf(c), step);
            break;
        case SDLK_a:
            move(rightOf(c), -step);
            break;
        case SDLK_e:
            move({0, 1, 0}, step);
            break;
        case SDLK_q:
            move({0, 1, 0}, -step);
            break;
        case SDLK_LEFT:
            c.yawDegrees -= kTurnDegrees;
            break;
        case SDLK_RIGHT:
            c.yawDegrees += kTurnDegrees;
            break;
        case SDLK_UP:
            c.pitchDegrees = std::min(c.pitchDegrees + kTurnDegrees, 89.0);
            break;
        case SDLK_DOWN:
            c.pitchDegrees = std::max(c.pitchDegrees - kTurnDegrees, -89.0);
            break;
        case SDLK_PLUS:
        case SDLK_EQUALS:
        case SDLK_KP_PLUS:
            s.maxReflections = std::min(s.maxReflections + 1, 16);
            break;
        case SDLK_MINUS:
        case SDLK_KP_MINUS:
            s.maxReflections = std::max(s.maxReflections - 1, 0);
            break;
        case SDLK_h:
            s.shadows = !s.shadows;
            break;
        case SDLK_t:
            s.textures = !s.textures;
            break;
        case SDLK_f:
            s.faceShading = !s.faceShading;
            break;
        case SDLK_m:
            s.reflectionMode =
                s.reflectionMode == voxel::ShadeOptions::ReflectionMode::RunningAverage
                    ? voxel::ShadeOptions::ReflectionMode::EnergyConserving
                    : voxel::ShadeOptions::ReflectionMode::RunningAverage;
            break;
        case SDLK_j:
            setSun(sunAzimuth_ - 15.0, sunElevation_);
            break;
        case SDLK_l:
            setSun(sunAzimuth_ + 15.0, sunElevation_);
            break;
        case SDLK_i:
            setSun(sunAzimuth_, sunElevation_ + 10.0);
            break;
        case SDLK_k:
            setSun(sunAzimuth_, sunElevation_ - 10.0);
            break;
        case SDLK_c:
            state_.solver.kind = nextVoxelSolver(state_.solver.kind);
            break;
        default:
            if (!applyVoxelSurfaceKey(static_cast<int>(key), state_)) return;
            break;
    }
    changed();
}

void ModeVoxel::handleEvent(const SDL_Event& event, const ViewRect& view) {
    switch (event.type) {
        case SDL_KEYDOWN:
            held_.insert(event.key.keysym.sym);
            if (!event.key.repeat)
                handleKey(event.key.keysym.sym, (event.key.keysym.mod & KMOD_SHIFT) != 0,
                          (event.key.keysym.mod & KMOD_CTRL) != 0);
            break;
        case SDL_KEYUP:
            held_.erase(event.key.keysym.sym);
            break;
        case SDL_WINDOWEVENT:
            // Key releases after the focus left never arrive: stop flying.
            if (event.window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
                held_.clear();
                looking_ = false;
            }
            break;
        case SDL_MOUSEBUTTONDOWN:
            if (event.button.button == SDL_BUTTON_RIGHT) {
                looking_ = true;
            } else if (event.button.button == SDL_BUTTON_LEFT) {
                const Vec2d u = view.toUnit(event.button.x, event.button.y);
                const FlyCamera& c = state_.camera;
                auto camera = voxel::Camera::create(c.position, c.yawDegrees, c.pitchDegrees,
                                                    c.fovYDegrees, state_.width, state_.height);
                if (!camera || u.x < 0 || u.y < 0 || u.x > 1 || u.y > 1) break;
                VoxelEdit edit;
                edit.ray = camera->rayAt(u.x * state_.width, u.y * state_.height);
                edit.add = held_.count(SDLK_LSHIFT) || held_.count(SDLK_RSHIFT) ||
                           (SDL_GetModState() & KMOD_SHIFT) != 0;
                edit.colour = {static_cast<std::uint8_t>(editColour_[0] * 255.0f + 0.5f),
                               static_cast<std::uint8_t>(editColour_[1] * 255.0f + 0.5f),
                               static_cast<std::uint8_t>(editColour_[2] * 255.0f + 0.5f), 255};
                state_.edits.push_back(edit);
                saver_.edit(edit);
                changed();
            }
            break;
        case SDL_MOUSEBUTTONUP:
            if (event.button.button == SDL_BUTTON_RIGHT) looking_ = false;
            break;
        case SDL_MOUSEMOTION:
            if (looking_) {
                FlyCamera& c = state_.camera;
                c.yawDegrees += event.motion.xrel * kLookDegreesPerPixel;
                c.pitchDegrees = std::clamp(
                    c.pitchDegrees - event.motion.yrel * kLookDegreesPerPixel, -89.0, 89.0);
                changed();
            }
            break;
        default:
            break;
    }
}

void ModeVoxel::update(double seconds) {
    const double speed = 0.12 * std::max({worldSize_.x, worldSize_.y, worldSize_.z});
    const FlyCamera& c = state_.camera;
    const double d = speed * std::min(seconds, 0.1);
    if (held_.count(SDLK_w)) move(forwardOf(c), d);
    if (held_.count(SDLK_s) && (SDL_GetModState() & KMOD_CTRL) == 0) move(forwardOf(c), -d);
    if (held_.count(SDLK_d)) move(rightOf(c), d);
    if (held_.count(SDLK_a)) move(rightOf(c), -d);
    if (held_.count(SDLK_e)) move({0, 1, 0}, d);
    if (held_.count(SDLK_q)) move({0, 1, 0}, -d);
    if (!dirty_) return;
    dirty_ = false;
    ++generation_;
    state_.restart = restart_;
    restart_ = false;
    worker_.post(state_, generation_);
    state_.edits.clear();
}

std::shared_ptr<const Frame> ModeVoxel::latestFrame(bool* fresh) {
    return worker_.latest(fresh);
}

bool ModeVoxel::frameCurrent() {
    auto frame = worker_.latest();
    return frame && !dirty_ && frame->generation == generation_;
}

bool ModeVoxel::frameConverged() {
    auto frame = worker_.latest();
    return frame && !dirty_ && frame->generation == generation_ && frame->converged;
}

void ModeVoxel::drawStats() {
    auto frame = worker_.latest();
    if (state_.solver.kind != VoxelSolver::PathTrace || !frame || frame->samples == 0) return;
    ImGui::Text("path tracer: %d / %d samples per pixel%s", frame->samples,
                state_.solver.path.samplesPerPixel, frame->converged ? " (done)" : "");
    if (std::isfinite(frame->relativeError)) {
        ImGui::Text("relative standard error %.2f%%", 100.0 * frame->relativeError);
    } else {
        ImGui::TextUnformatted("relative standard error n/a (needs 2 samples and light)");
    }
}

// Combo over an enum's values, by name; true when changed.
template <typename E, int N>
bool enumCombo(const char* label, E& value, const char* (&names)[N]) {
    int index = static_cast<int>(value);
    if (!ImGui::Combo(label, &index, names, N)) return false;
    value = static_cast<E>(index);
    return true;
}

void ModeVoxel::drawSurfacePanel() {
    voxel::ShadeOptions& s = state_.shading;
    post::PostOptions& p = state_.post;
    bool touched = false;
    const char* lightings[] = {"classic", "physical"};
    touched |= enumCombo("lighting (P)", s.lighting, lightings);
    const char* methods[] = {"hard", "exact", "MSM", "VSM", "SDF", "MRMA blend", "flood fill"};
    touched |= enumCombo("shadow method (V)", s.shadowSettings.method, methods);
    float radiusDegrees = static_cast<float>(s.sunAngularRadius * 180.0 / 3.14159265358979323846);
    if (ImGui::SliderFloat("sun angular radius", &radiusDegrees, 0.0f, 5.0f, "%.2f deg")) {
        s.sunAngularRadius = radiusDegrees * 3.14159265358979323846 / 180.0;
        touched = true;
    }
    const char* speculars[] = {"none", "Blinn-Phong", "GGX"};
    touched |= enumCombo("specular (G)", s.specular, speculars);
    const char* fresnels[] = {"Schlick", "exact"};
    touched |= enumCombo("Fresnel (Y)", s.fresnel, fresnels);
    touched |= ImGui::Checkbox("refraction (R)", &s.refraction);
    ImGui::SameLine();
    touched |= ImGui::Checkbox("normal maps (N)", &s.normalMaps);
    if (s.lighting == voxel::ShadeOptions::Lighting::Physical) {
        // The ray caster's sky light: traced with occlusion, or (0 rays) a constant share.
        touched |= ImGui::SliderInt("sky ambient rays", &s.skyAmbientRays, 0, 64);
        if (s.skyAmbientRays == 0) {
            touched |= ImGui::SliderFloat("sky ambient share", &s.skyAmbient, 0.0f, 1.0f, "%.2f");
        }
    }
    const char* filters[] = {"nearest", "trilinear", "anisotropic"};
    touched |= enumCombo("texture filter (X)", s.textureFilter, filters);
    touched |= ImGui::SliderInt("samples per pixel (, .)", &s.samplesPerPixel, 1, 64);
    // Radiance cascades: the pixels of strong contrast drawn again (0: off).
    touched |= ImGui::SliderInt("adaptive samples (cascades)", &s.adaptiveSamples, 0, 64);
    touched |= ImGui::SliderFloat("bloom (O)", &p.bloom.strength, 0.0f, 1.0f, "%.2f");
    touched |= ImGui::SliderInt("bloom levels", &p.bloom.levels, 1, 8);
    touched |= ImGui::SliderFloat("internal scale", &p.internalScale, post::kMinInternalScale, 1.0f,
                                  "%.2f");
    const char* upscalers[] = {"bilinear", "edge-aware"};
    touched |= enumCombo("upscaler", p.upscaler, upscalers);
    touched |= ImGui::Checkbox("temporal upscaling (reprojection)", &state_.temporal);
    touched |= ImGui::SliderFloat("sharpening", &p.sharpness, 0.0f, 1.0f, "%.2f");
    ImGui::Text("upscaling (U): %s", upscalingLabel(state_).c_str());
    if (touched) changed();
}

void ModeVoxel::drawPanel() {
    voxel::ShadeOptions& s = state_.shading;
    FlyCamera& c = state_.camera;
    ImGui::Text("camera %.1f %.1f %.1f  yaw %.0f pitch %.0f", c.position.x, c.position.y,
                c.position.z, c.yawDegrees, c.pitchDegrees);
    bool restart = false;
    if (drawVoxelSolverPanel(state_.solver, &restart)) {
        dirty_ = true;
        restart_ = restart_ || restart;
    }
    if (ImGui::SliderInt("reflections (+/-)", &s.maxReflections, 0, 16)) changed();
    if (ImGui::Checkbox("face shading (F)", &s.faceShading)) changed();
    ImGui::SameLine();
    if (ImGui::Checkbox("shadows (H)", &s.shadows)) changed();
    ImGui::SameLine();
    if (ImGui::Checkbox("textures (T)", &s.textures)) changed();
    int mode = s.reflectionMode == voxel::ShadeOptions::ReflectionMode::RunningAverage ? 0 : 1;
    const char* modes[] = {"running average", "energy conserving"};
    if (ImGui::Combo("reflection mode (M)", &mode, modes, 2)) {
        s.reflectionMode = mode == 0 ? voxel::ShadeOptions::ReflectionMode::RunningAverage
                                     : voxel::ShadeOptions::ReflectionMode::EnergyConserving;
        changed();
    }
    float azimuth = static_cast<float>(sunAzimuth_), elevation = static_cast<float>(sunElevation_);
    bool sun = ImGui::SliderFloat("sun azimuth (J/L)", &azimuth, -180.0f, 180.0f, "%.0f deg");
    sun |= ImGui::SliderFloat("sun elevation (I/K)", &elevation, -10.0f, 90.0f, "%.0f deg");
    if (sun) setSun(azimuth, elevation);
    // The sky: the scene's gradient, or the Preetham clear sky around the sun.
    const char* skies[] = {"gradient", "Preetham clear sky"};
    if (enumCombo("sky", s.skyModel, skies)) changed();
    if (s.skyModel == voxel::ShadeOptions::SkyModel::Preetham) {
        if (ImGui::SliderFloat("turbidity", &s.skyTurbidity, 2.0f, 10.0f, "%.1f")) changed();
        if (ImGui::SliderFloat("zenith luminance", &s.skyZenithLuminance, 0.0f, 4.0f, "%.2f")) {
            changed();
        }
    }
    // Exposure only changes how the light is shown: the path tracer keeps its samples.
    if (ImGui::SliderFloat("exposure", &state_.exposure, -6.0f, 6.0f, "%.1f stops")) dirty_ = true;
    drawSurfacePanel();
    ImGui::ColorEdit3("new voxel colour", editColour_);
    ImGui::TextUnformatted("left click removes, Shift+left click adds");
    if (ImGui::Button("Save .vox")) save();
    ImGui::SameLine();
    ImGui::TextUnformatted(saver_.status().empty() ? ("Ctrl+S: " + saver_.path()).c_str()
                                                   : saver_.status().c_str());
}

}  // namespace luxel::viewer
