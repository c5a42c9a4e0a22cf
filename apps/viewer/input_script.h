// Scripted input for luxel-view (--script FILE): one event per line, run in order, so tests and
// demos drive the viewer deterministically. Format (docs/viewer.md):
//
//   # comment                      blank lines and comments are ignored
//   [at SECONDS] COMMAND ARGS      "at" waits until SECONDS after start before the command
//   wait SECONDS | wait_frames N | wait_render | wait_converged
//   key NAME | key_down NAME | key_up NAME        NAME: an SDL key name, optional ctrl+/shift+/alt+
//   mouse_down X Y [left|middle|right] | mouse_move X Y | mouse_up X Y [button] | click X Y
//   [button] | wheel NOTCHES
//   screenshot FILE.png | screenshot_window FILE.png | quit
//
// Mouse coordinates are window pixels. Parsing is pure (no SDL) so it is unit-tested.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "luxel/core/error.h"

namespace luxel::viewer {

enum class ScriptCommand {
    Wait,
    WaitFrames,
    WaitRender,
    WaitConverged,
    Key,
    KeyDown,
    KeyUp,
    MouseDown,
    MouseMove,
    MouseUp,
    Click,
    Wheel,
    Screenshot,
    ScreenshotWindow,
    Resize,
    Quit,
};

enum class MouseButton { Left = 1, Middle = 2, Right = 3 };

struct KeyChord {
    std::string name;  // SDL key name without modifiers, e.g. "Space", "S", "Up"
    bool ctrl = false, shift = false, alt = false;
};

struct ScriptEvent {
    ScriptCommand command = ScriptCommand::Quit;
    int line = 0;          // 1-based line in the script file
    double at = -1.0;      // "at SECONDS" prefix; < 0 when absent
    double seconds = 0.0;  // wait
    int frames = 0;        // wait_frames
    KeyChord key;          // key commands
    int x = 0, y = 0;      // mouse commands, window pixels; wheel: y notches (up positive)
    MouseButton button = MouseButton::Left;
    std::string path;  // screenshot commands
};

struct Script {
    std::string name;  // file name, for messages
    std::vector<ScriptEvent> events;
};

// The longest wait a script may ask for ("wait", "at"): a typo such as 1e308 would hang a test.
inline constexpr double kMaxScriptSeconds = 3600.0;

// Tells whether a key name (without modifiers) is known; the viewer asks SDL.
using KeyNameCheck = std::function<bool(const std::string& name)>;

// Errors read "FILE:LINE: what is wrong". loadScript reads regular files only (a directory or a
// FIFO is an error naming the path, not an empty or endless script).
Result<Script> parseScript(std::string_view text, const std::string& name,
                           const KeyNameCheck& isKnownKey);
Result<Script> loadScript(const std::string& path, const KeyNameCheck& isKnownKey);

}  // namespace luxel::viewer
