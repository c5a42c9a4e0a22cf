// ImGui statistics overlay.
#include "overlay.h"

#include <imgui.h>

namespace luxel::viewer {

void RateMeter::tick(double seconds) {
    if (windowStart_ < 0.0) {
        windowStart_ = seconds;
        return;
    }
    ++count_;
    // Events per second over windows of at least half a second: steady enough to read.
    if (seconds - windowStart_ >= 0.5) {
        rate_ = count_ / (seconds - windowStart_);
        windowStart_ = seconds;
        count_ = 0;
    }
}

void drawOverlay(const OverlayInfo& info, ViewerMode& mode) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin("luxel-view", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::Text("%s mode   window %.0f fps   render %.1f fps", mode.name().c_str(), info.windowFps,
                info.renderFps);
    ImGui::Text("internal %dx%d   window %dx%d", mode.internalWidth(), mode.internalHeight(),
                info.windowWidth, info.windowHeight);
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
    if (ImGui::CollapsingHeader("controls")) mode.drawPanel();
    ImGui::End();
}

}  // namespace luxel::viewer
