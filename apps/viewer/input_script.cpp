// Parser for --script files (format in input_script.h and docs/viewer.md).
#include "input_script.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "luxel/core/file_io.h"

namespace luxel::viewer {
namespace {

std::vector<std::string> splitWords(std::string_view line) {
    std::vector<std::string> words;
    std::istringstream in{std::string(line)};
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

bool parseNumber(const std::string& text, double& value) {
    char* end = nullptr;
    errno = 0;
    value = std::strtod(text.c_str(), &end);
    return end != text.c_str() && *end == '\0' && errno == 0 && std::isfinite(value);
}

bool parseInt(const std::string& text, int& value) {
    double v = 0;
    if (!parseNumber(text, v) || v != std::floor(v) || std::fabs(v) > 1e7) return false;
    value = static_cast<int>(v);
    return true;
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

struct CommandSpec {
    const char* name;
    ScriptCommand command;
};
constexpr CommandSpec kCommands[] = {
    {"wait", ScriptCommand::Wait},
    {"wait_frames", ScriptCommand::WaitFrames},
    {"wait_render", ScriptCommand::WaitRender},
    {"wait_converged", ScriptCommand::WaitConverged},
    {"key", ScriptCommand::Key},
    {"key_down", ScriptCommand::KeyDown},
    {"key_up", ScriptCommand::KeyUp},
    {"mouse_down", ScriptCommand::MouseDown},
    {"mouse_move", ScriptCommand::MouseMove},
    {"mouse_up", ScriptCommand::MouseUp},
    {"click", ScriptCommand::Click},
    {"wheel", ScriptCommand::Wheel},
    {"screenshot", ScriptCommand::Screenshot},
    {"screenshot_window", ScriptCommand::ScreenshotWindow},
    {"resize", ScriptCommand::Resize},
    {"quit", ScriptCommand::Quit},
};

// Parses the words after the command name into `event`; returns "" or what is wrong.
std::string parseArguments(const std::vector<std::string>& args, ScriptEvent& event,
                           const KeyNameCheck& isKnownKey) {
    auto expectCount = [&](std::size_t lo, std::size_t hi, const char* usage) -> std::string {
        if (args.size() < lo || args.size() > hi) return std::string("expected ") + usage;
        return "";
    };
    switch (event.command) {
        case ScriptCommand::Wait:
            if (auto e = expectCount(1, 1, "'wait SECONDS'"); !e.empty()) return e;
            if (!parseNumber(args[0], event.seconds) || event.seconds < 0 ||
                event.seconds > kMaxScriptSeconds) {
                return "'" + args[0] + "' is not a number of seconds in 0.." +
                       std::to_string(static_cast<int>(kMaxScriptSeconds));
            }
            return "";
        case ScriptCommand::WaitFrames:
            if (auto e = expectCount(1, 1, "'wait_frames N'"); !e.empty()) return e;
            if (!parseInt(args[0], event.frames) || event.frames < 0) {
                return "'" + args[0] + "' is not a frame count >= 0";
            }
            return "";
        case ScriptCommand::WaitRender:
        case ScriptCommand::WaitConverged:
        case ScriptCommand::Quit:
            return expectCount(0, 0, "no arguments");
        case ScriptCommand::Key:
        case ScriptCommand::KeyDown:
        case ScriptCommand::KeyUp: {
            if (auto e = expectCount(1, 1, "one key name (e.g. 'key Space', 'key ctrl+s')");
                !e.empty())
                return e;
            std::string name = args[0];
            for (;;) {
                const std::string l = lower(name);
                if (l.rfind("ctrl+", 0) == 0) {
                    event.key.ctrl = true;
                    name = name.substr(5);
                } else if (l.rfind("shift+", 0) == 0) {
                    event.key.shift = true;
                    name = name.substr(6);
                } else if (l.rfind("alt+", 0) == 0) {
                    event.key.alt = true;
                    name = name.substr(4);
                } else {
                    break;
                }
            }
            if (name.empty() || (isKnownKey && !isKnownKey(name))) {
                return "unknown key '" + args[0] + "' (SDL key names: Space, Up, A, F12, ...)";
            }
            event.key.name = name;
            return "";
        }
        case ScriptCommand::MouseDown:
        case ScriptCommand::MouseUp:
        case ScriptCommand::Click:
        case ScriptCommand::MouseMove: {
            const bool takesButton = event.command != ScriptCommand::MouseMove;
            if (auto e = expectCount(2, takesButton ? 3 : 2,
                                     takesButton ? "'X Y [left|middle|right]'" : "'X Y'");
                !e.empty())
                return e;
            if (!parseInt(args[0], event.x) || !parseInt(args[1], event.y)) {
                return "mouse position '" + args[0] + " " + args[1] + "' is not two integers";
            }
            if (args.size() == 3) {
                const std::string b = lower(args[2]);
                if (b == "left") {
                    event.button = MouseButton::Left;
                } else if (b == "middle") {
                    event.button = MouseButton::Middle;
                } else if (b == "right") {
                    event.button = MouseButton::Right;
                } else {
                    return "mouse button '" + args[2] + "' is not left, middle or right";
                }
            }
            return "";
        }
        case ScriptCommand::Wheel:
            if (auto e = expectCount(1, 1, "'wheel NOTCHES' (positive: up, away from you)");
                !e.empty())
                return e;
            if (!parseInt(args[0], event.y) || event.y < -100 || event.y > 100 || event.y == 0) {
                return "'" + args[0] + "' is not a wheel step in -100..100 other than 0";
            }
            return "";
        case ScriptCommand::Resize:
            if (auto e = expectCount(2, 2, "'resize WIDTH HEIGHT'"); !e.empty()) return e;
            if (!parseInt(args[0], event.x) || !parseInt(args[1], event.y) || event.x < 1 ||
                event.y < 1 || event.x > 16384 || event.y > 16384) {
                return "window size '" + args[0] + " " + args[1] + "' is not two sides in 1..16384";
            }
            return "";
        case ScriptCommand::Screenshot:
        case ScriptCommand::ScreenshotWindow:
            if (auto e = expectCount(1, 1, "one file name ending in .png"); !e.empty()) return e;
            if (args[0].size() < 5 || lower(args[0].substr(args[0].size() - 4)) != ".png") {
                return "screenshot file '" + args[0] + "' must end in .png";
            }
            event.path = args[0];
            return "";
    }
    return "unhandled command";
}

}  // namespace

Result<Script> parseScript(std::string_view text, const std::string& name,
                           const KeyNameCheck& isKnownKey) {
    Script script{name, {}};
    int lineNumber = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++lineNumber;
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
            line = line.substr(0, hash);
        }
        std::vector<std::string> words = splitWords(line);
        if (words.empty()) {
            if (end == text.size()) break;
            continue;
        }
        const SourceLocation where{name, lineNumber, 0, ""};
        ScriptEvent event;
        event.line = lineNumber;
        std::size_t first = 0;
        if (words[0] == "at") {
            if (words.size() < 3 || !parseNumber(words[1], event.at) || event.at < 0 ||
                event.at > kMaxScriptSeconds) {
                return Error(where, "expected 'at SECONDS COMMAND ...' with SECONDS in 0.." +
                                        std::to_string(static_cast<int>(kMaxScriptSeconds)));
            }
            first = 2;
        }
        const std::string& commandName = words[first];
        bool known = false;
        for (const CommandSpec& spec : kCommands) {
            if (commandName == spec.name) {
                event.command = spec.command;
                known = true;
            }
        }
        if (!known) return Error(where, "unknown command '" + commandName + "'");
        const std::vector<std::string> args(words.begin() + static_cast<long>(first) + 1,
                                            words.end());
        if (std::string problem = parseArguments(args, event, isKnownKey); !problem.empty()) {
            return Error(where, commandName + ": " + problem);
        }
        script.events.push_back(std::move(event));
        if (end == text.size()) break;
    }
    return script;
}

Result<Script> loadScript(const std::string& path, const KeyNameCheck& isKnownKey) {
    auto text = readFileBytes(path, "script", std::uintmax_t{1} << 20);
    if (!text) return text.error();
    return parseScript(*text, path, isKnownKey);
}

}  // namespace luxel::viewer
