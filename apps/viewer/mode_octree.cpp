// Octree mode input and panel.
#include "mode_octree.h"

#include <imgui.h>

#include <algorithm>

#include "luxel/core/memory.h"

namespace luxel::viewer {
namespace {

constexpr double kTurnDegrees = 5.0;  // arrow keys

}  // namespace

ModeOctree::ModeOctree(scene::OctreeScene scene, int width, int height, float exposure,
                       std::unique_ptr<OctreeFrameSource> source)
    : width_(width),
      height_(height),
      source_(scene.source),
      stats_(octree::measure(scene.tree)),
      extent_(scene.tree.extent()),
      controls_(scene.camera, extent_, scene.render, width, height, exposure),
      worker_(std::make_unique<RendererOctree>(
          std::make_shared<const octree::Octree>(std::move(scene.tree)), std::move(source))) {}

void ModeOctree::handleKey(SDL_Keycode key, bool shift) {
    // A tap moves one step, so scripted and single presses have a visible, repeatable effect;
    // holding the key keeps moving in update().
    const double step =
        std::max(1.0, std::max({extent_.x, extent_.y, extent_.z}) / 64.0) * (shift ? 4.0 : 1.0);
    OctreeControls& c = controls_;
    switch (key) {
        case SDLK_w:
            c.travel(step, 0, 0);
            break;
        case SDLK_s:
            c.travel(-step, 0, 0);
            break;
        case SDLK_d:
            c.travel(0, step, 0);
            break;
        case SDLK_a:
            c.travel(0, -step, 0);
            break;
        case SDLK_e:
            c.travel(0, 0, step);
            break;
        case SDLK_q:
            c.travel(0, 0, -step);
            break;
        case SDLK_LEFT:
            c.turn(-kTurnDegrees, 0);
            break;
        case SDLK_RIGHT:
            c.turn(kTurnDegrees, 0);
            break;
        case SDLK_UP:
            c.turn(0, kTurnDegrees);
            break;
        case SDLK_DOWN:
            c.turn(0, -kTurnDegrees);
            break;
        case SDLK_c:
            c.apply(OctreeAction::ToggleCamera);
            break;
        case SDLK_o:
            c.orbitVolumeCentre();
            break;
        case SDLK_HOME:
            c.apply(OctreeAction::ResetView);
            break;
        case SDLK_v:
            c.apply(OctreeAction::CycleMode);
            break;
        case SDLK_h:
            c.apply(OctreeAction::ToggleShadows);
            break;
        case SDLK_r:
            c.apply(OctreeAction::ToggleScattering);
            break;
        case SDLK_PLUS:
        case SDLK_EQUALS:
        case SDLK_KP_PLUS:
            c.apply(OctreeAction::OpacityUp);
            break;
        case SDLK_MINUS:
        case SDLK_KP_MINUS:
            c.apply(OctreeAction::OpacityDown);
            break;
        case SDLK_PERIOD:
            c.apply(OctreeAction::ThresholdUp);
            break;
        case SDLK_COMMA:
            c.apply(OctreeAction::ThresholdDown);
            break;
        case SDLK_j:
            c.apply(OctreeAction::SunAzimuthDown);
            break;
        case SDLK_l:
            c.apply(OctreeAction::SunAzimuthUp);
            break;
        case SDLK_i:
            c.apply(OctreeAction::SunElevationUp);
            break;
        case SDLK_k:
            c.apply(OctreeAction::SunElevationDown);
            break;
        case SDLK_LEFTBRACKET:
            c.apply(OctreeAction::ExposureDown);
            break;
        case SDLK_RIGHTBRACKET:
            c.apply(OctreeAction::ExposureUp);
            break;
        default:
            break;
    }
}

void ModeOctree::handleEvent(const SDL_Event& event, const ViewRect&) {
    switch (event.type) {
        case SDL_KEYDOWN:
            held_.insert(event.key.keysym.sym);
            if (!event.key.repeat)
                handleKey(event.key.keysym.sym, (event.key.keysym.mod & KMOD_SHIFT) != 0);
            break;
        case SDL_KEYUP:
            held_.erase(event.key.keysym.sym);
            break;
        case SDL_WINDOWEVENT:
            // Key releases after the focus left never arrive: stop flying.
            if (event.window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
                held_.clear();
                dragging_ = false;
            }
            break;
        case SDL_MOUSEBUTTONDOWN:
            // Left drag orbits (the WebGL octree design); right drag is voxel mode's mouse look.
            // Either button turns the view the way the camera mode says.
            if (event.button.button == SDL_BUTTON_LEFT || event.button.button == SDL_BUTTON_RIGHT)
                dragging_ = true;
            break;
        case SDL_MOUSEBUTTONUP:
            if (event.button.button == SDL_BUTTON_LEFT || event.button.button == SDL_BUTTON_RIGHT)
                dragging_ = false;
            break;
        case SDL_MOUSEMOTION:
            if (dragging_) controls_.drag(event.motion.xrel, event.motion.yrel);
            break;
        case SDL_MOUSEWHEEL: {
            const int notches =
                event.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -event.wheel.y : event.wheel.y;
            if (notches != 0) controls_.zoom(notches);
            break;
        }
        default:
            break;
    }
}

void ModeOctree::update(double seconds) {
    const double d = 0.12 * std::max({extent_.x, extent_.y, extent_.z}) * std::min(seconds, 0.1);
    OctreeControls& c = controls_;
    if (held_.count(SDLK_w)) c.travel(d, 0, 0);
    if (held_.count(SDLK_s)) c.travel(-d, 0, 0);
    if (held_.count(SDLK_d)) c.travel(0, d, 0);
    if (held_.count(SDLK_a)) c.travel(0, -d, 0);
    if (held_.count(SDLK_e)) c.travel(0, 0, d);
    if (held_.count(SDLK_q)) c.travel(0, 0, -d);
    if (!c.takeChanged()) return;
    ++generation_;
    worker_.post(c.state(), generation_);
}

std::shared_ptr<const Frame> ModeOctree::latestFrame(bool* fresh) {
    return worker_.latest(fresh);
}

bool ModeOctree::frameCurrent() {
    auto frame = worker_.latest();
    return frame && frame->generation == generation_;
}

bool ModeOctree::frameConverged() {
    auto frame = worker_.latest();
    return frame && frame->generation == generation_ && frame->converged;
}

void ModeOctree::drawStats() {
    ImGui::Text("octree %s: depth %d (%d^3), %llu octants, %s", source_.c_str(), stats_.depth,
                1 << stats_.depth, static_cast<unsigned long long>(stats_.octants),
                formatBytes(stats_.geometryBytes).c_str());
    if (stats_.attributeBytes > 0) {
        ImGui::SameLine();
        ImGui::Text("+ %s colours", formatBytes(stats_.attributeBytes).c_str());
    }
    ImGui::Text("  %.3g solid voxels, %.2f bits per solid voxel (geometry)",
                static_cast<double>(stats_.solidVoxels), stats_.bitsPerSolidVoxel);
}

void ModeOctree::drawPanel() {
    OctreeControls& c = controls_;
    const octree::OctreeRenderOptions& o = c.options();
    const OrbitFlyCamera& cam = c.camera();
    const Vec3d p = cam.position();
    ImGui::Text("camera %.1f %.1f %.1f  yaw %.0f pitch %.0f", p.x, p.y, p.z, cam.yawDegrees(),
                cam.pitchDegrees());
    int cameraMode = cam.orbiting() ? 0 : 1;
    const char* cameraModes[] = {"orbit (drag to rotate)", "fly (WASD/QE, drag to look)"};
    if (ImGui::Combo("camera (C)", &cameraMode, cameraModes, 2)) c.setOrbiting(cameraMode == 0);
    if (cam.orbiting()) {
        const Vec3d t = cam.target();
        ImGui::Text("target %.1f %.1f %.1f  distance %.1f", t.x, t.y, t.z, cam.distance());
        if (ImGui::Button("orbit the volume centre (O)")) c.orbitVolumeCentre();
        ImGui::SameLine();
    }
    if (ImGui::Button("reset view (Home)")) c.apply(OctreeAction::ResetView);

    int mode = static_cast<int>(o.mode);
    const char* modes[] = {"surface", "volume", "additive", "tiles (the design's proposal)"};
    if (ImGui::Combo("mode (V)", &mode, modes, 4)) c.setMode(static_cast<octree::OctreeMode>(mode));
    float scale = o.opacityScale;
    if (ImGui::SliderFloat("opacity scale (-/+)", &scale, kMinOpacityScale, kMaxOpacityScale,
                           "%.4g", ImGuiSliderFlags_Logarithmic)) {
        c.setOpacityScale(scale);
    }
    int window[2] = {o.windowLow, o.windowHigh};
    if (ImGui::SliderInt2("opacity window", window, 0, 255))
        c.setOpacityWindow(window[0], window[1]);
    int threshold = o.threshold;
    if (ImGui::SliderInt("surface threshold (,/.)", &threshold, 1, 255)) c.setThreshold(threshold);
    bool shadows = o.shadows;
    if (ImGui::Checkbox("shadows (H)", &shadows)) c.setShadows(shadows);
    ImGui::SameLine();
    bool scattering = o.scattering;
    if (ImGui::Checkbox("scattering (R)", &scattering)) c.setScattering(scattering);
    float radius = o.sunRadiusDegrees;
    if (ImGui::SliderFloat("sun radius", &radius, 0.0f, 10.0f, "%.1f deg")) c.setSunRadius(radius);
    float albedo = o.albedo;
    if (ImGui::SliderFloat("albedo", &albedo, 0.0f, 1.0f, "%.2f")) c.setAlbedo(albedo);
    float g = o.phaseG;
    if (ImGui::SliderFloat("phase g", &g, -kMaxPhaseG, kMaxPhaseG, "%.2f")) c.setPhaseG(g);
    float azimuth = static_cast<float>(c.sunAzimuth());
    float elevation = static_cast<float>(c.sunElevation());
    bool sun = ImGui::SliderFloat("sun azimuth (J/L)", &azimuth, -180.0f, 180.0f, "%.0f deg");
    sun |= ImGui::SliderFloat("sun elevation (I/K)", &elevation, -90.0f, 90.0f, "%.0f deg");
    if (sun) c.setSun(azimuth, elevation);
    float exposure = c.exposure();
    if (ImGui::SliderFloat("exposure ([/])", &exposure, -6.0f, 6.0f, "%.1f stops")) {
        c.setExposure(exposure);
    }
}

}  // namespace luxel::viewer
