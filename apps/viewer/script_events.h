// Turns script events into the SDL events real input would produce, so scripted runs go through
// the same handlers as a user's mouse and keyboard.
#pragma once

#include <SDL.h>

#include <string>
#include <vector>

#include "input_script.h"

namespace luxel::viewer {

// SDL key name lookup; '_' stands for a space ("Left_Shift" = "Left Shift").
SDL_Keycode keyFromName(const std::string& name);
bool isKnownKeyName(const std::string& name);

// Mouse state carried between scripted events (for motion deltas and held buttons).
struct ScriptedMouse {
    int x = 0, y = 0;
    Uint32 buttons = 0;
};

// Input events for one script event (none for screenshot, quit and waits).
std::vector<SDL_Event> toSdlEvents(const ScriptEvent& event, ScriptedMouse& mouse, Uint32 windowId);

}  // namespace luxel::viewer
