// ImGui statistics overlay.
#include "overlay.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace luxel::viewer {

void RateMeter::tick(double seconds) {
    if (windowStart_ < 0.0) {
        windowStart_ = seconds;
        return;
    }
    ++count_;
    // Events per second over windows of at least half a second: steady enough to read. Until
    // the first window is complete, the rate so far, so the first frames do not read 0.
    const double elapsed = seconds - windowStart_;
    if (elapsed >= 0.5) {
        rate_ = count_ / elapsed;
        windowStart_ = seconds;
        count_ = 0;
        windowsDone_ = true;
    } else if (!windowsDone_ && elapsed > 0.0) {
        rate_ = count_ / elapsed;
    }
}

namespace {

// "12.3 fps", or "- fps" while unknown.
std::string fpsText(double rate) {
    if (rate <= 0.0) return "- fps";
    char text[32];
    std::snprintf(text, sizeof text, "%.*f fps", rate < 10.0 ? 1 : 0, rate);
    return text;
}

}  // namespace

void drawOverlay(const OverlayInfo& info, ViewerMode& mode) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.75f);
    // Never larger than the window: a tall panel scrolls instead of being cut off.
    ImGui::SetNextWindowSizeConstraints(
        ImVec2(0, 0), ImVec2(std::max(64.0f, static_cast<float>(info.windowWidth) - 16.0f),
                             std::max(64.0f, static_cast<float>(info.windowHeight) - 16.0f)));
    ImGui::Begin("luxel-view", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::Text("%s mode   window %s   render %s", mode.name().c_str(),
                fpsText(info.windowFps).c_str(), fpsText(info.renderFps).c_str());
    ImGui::Text("internal %dx%d%s   window %dx%d", mode.internalWidth(), mode.internalHeight(),
                info.adaptiveTargetFps > 0.0 ? " (adaptive)" : "", info.windowWidth,
                info.windowHeight);
    if (const Frame* f = info.frame) {
        ImGui::Text("backend %s   device %s", f->backend.c_str(), f->device.c_str());
        ImGui::Text("frame %.1f ms%s", f->renderMilliseconds,
                    f->samples > 0 ? "" : (f->converged ? "" : "  (refining)"));
        if (f->samples > 0) {
            ImGui::SameLine();
            ImGui::Text("  %d rays/pixel%s", f->samples, f->converged ? "" : " (refining)");
        }
        // The default font is monospaced: padded text lines up without a table.
        for (const PassTime& p : f->passes) {
            ImGui::Text("  %-18s %8.2f ms", p.name.c_str(), p.milliseconds);
        }
        if (!f->note.empty()) ImGui::TextWrapped("note: %s", f->note.c_str());
    } else {
        ImGui::TextUnformatted("rendering the first frame...");
    }
    mode.drawStats();
    if (!info.lastScreenshot.empty()) ImGui::Text("wrote %s", info.lastScreenshot.c_str());
    ImGui::TextUnformatted("F1 panels   F12 screenshot   Esc quit");
    if (mode.takePanelRequest()) ImGui::SetNextItemOpen(true);
    if (ImGui::CollapsingHeader("controls")) mode.drawPanel();
    ImGui::End();
}

}  // namespace luxel::viewer
