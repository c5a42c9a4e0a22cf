// The window: SDL video + SDL_Renderer, Dear ImGui panels, the frame loop, scripted input,
// screenshots and recording. Everything expensive happens on the mode's render thread.
#pragma once

#include <memory>
#include <optional>

#include "input_script.h"
#include "viewer_mode.h"
#include "viewer_options.h"

namespace luxel::viewer {

// Exit codes: 0 normal quit, 1 bad input or a failed script step, 2 no display.
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitNoDisplay = 2;

// Opens the window (fails with a message when there is no display) and runs until quit.
int runApp(const ViewerOptions& options, ViewerMode& mode, std::optional<Script> script,
           int windowWidth, int windowHeight);

}  // namespace luxel::viewer
