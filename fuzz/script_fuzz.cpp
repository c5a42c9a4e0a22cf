// libFuzzer target for luxel-view's --script parser (luxel::viewer::parseScript): any bytes must
// give a script or an Error, never a crash or a sanitizer report. Every event of a script that
// parses must hold what the player relies on: a line inside the text, waits within
// kMaxScriptSeconds, a known key, wheel steps and window sizes in range, a .png screenshot path.
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "input_script.h"

namespace {

using namespace luxel::viewer;

// A stand-in for SDL's key names: a few words and every single letter or digit.
bool knownKey(const std::string& name) {
    static const char* const kNames[] = {"Space", "Up", "Down", "Left", "Right", "F12", "Escape"};
    if (name.size() == 1) return std::isalnum(static_cast<unsigned char>(name[0])) != 0;
    return std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}

bool validEvent(const ScriptEvent& e, int lines) {
    if (e.line < 1 || e.line > lines) return false;
    if (e.at > kMaxScriptSeconds) return false;
    switch (e.command) {
        case ScriptCommand::Wait:
            return e.seconds >= 0 && e.seconds <= kMaxScriptSeconds;
        case ScriptCommand::WaitFrames:
            return e.frames >= 0;
        case ScriptCommand::Key:
        case ScriptCommand::KeyDown:
        case ScriptCommand::KeyUp:
            return knownKey(e.key.name);
        case ScriptCommand::Wheel:
            return e.y != 0 && e.y >= -100 && e.y <= 100;
        case ScriptCommand::Resize:
            return e.x >= 1 && e.y >= 1 && e.x <= 16384 && e.y <= 16384;
        case ScriptCommand::Screenshot:
        case ScriptCommand::ScreenshotWindow:
            return e.path.size() >= 5;
        default:
            return true;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const luxel::Result<Script> script = parseScript(text, "fuzz.script", knownKey);
    if (!script) {
        if (script.error().message().empty()) __builtin_trap();  // an error says what is wrong
        return 0;
    }
    const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n')) + 1;
    for (const ScriptEvent& e : script->events) {
        if (!validEvent(e, lines)) __builtin_trap();
    }
    return 0;
}
