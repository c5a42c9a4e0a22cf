// ScriptEvent -> SDL_Event.
#include "script_events.h"

#include <algorithm>

namespace luxel::viewer {
namespace {

SDL_Event keyEvent(Uint32 type, const KeyChord& chord, Uint32 windowId) {
    SDL_Event e{};
    e.type = type;
    e.key.windowID = windowId;
    e.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
    e.key.keysym.sym = keyFromName(chord.name);
    e.key.keysym.scancode = SDL_GetScancodeFromKey(e.key.keysym.sym);
    Uint16 mod = KMOD_NONE;
    if (chord.ctrl) mod |= KMOD_LCTRL;
    if (chord.shift) mod |= KMOD_LSHIFT;
    if (chord.alt) mod |= KMOD_LALT;
    e.key.keysym.mod = mod;
    return e;
}

Uint8 sdlButton(MouseButton b) {
    switch (b) {
        case MouseButton::Left:
            return SDL_BUTTON_LEFT;
        case MouseButton::Middle:
            return SDL_BUTTON_MIDDLE;
        case MouseButton::Right:
            return SDL_BUTTON_RIGHT;
    }
    return SDL_BUTTON_LEFT;
}

SDL_Event motionEvent(int x, int y, ScriptedMouse& mouse, Uint32 windowId) {
    SDL_Event e{};
    e.type = SDL_MOUSEMOTION;
    e.motion.windowID = windowId;
    e.motion.x = x;
    e.motion.y = y;
    e.motion.xrel = x - mouse.x;
    e.motion.yrel = y - mouse.y;
    e.motion.state = mouse.buttons;
    mouse.x = x;
    mouse.y = y;
    return e;
}

SDL_Event buttonEvent(Uint32 type, const ScriptEvent& event, ScriptedMouse& mouse,
                      Uint32 windowId) {
    SDL_Event e{};
    e.type = type;
    e.button.windowID = windowId;
    e.button.button = sdlButton(event.button);
    e.button.state = type == SDL_MOUSEBUTTONDOWN ? SDL_PRESSED : SDL_RELEASED;
    e.button.clicks = 1;
    e.button.x = event.x;
    e.button.y = event.y;
    if (type == SDL_MOUSEBUTTONDOWN) {
        mouse.buttons |= SDL_BUTTON(e.button.button);
    } else {
        mouse.buttons &= ~SDL_BUTTON(e.button.button);
    }
    return e;
}

}  // namespace

SDL_Keycode keyFromName(const std::string& name) {
    std::string spaced = name;
    std::replace(spaced.begin(), spaced.end(), '_', ' ');
    return SDL_GetKeyFromName(spaced.c_str());
}

bool isKnownKeyName(const std::string& name) {
    return keyFromName(name) != SDLK_UNKNOWN;
}

std::vector<SDL_Event> toSdlEvents(const ScriptEvent& event, ScriptedMouse& mouse,
                                   Uint32 windowId) {
    switch (event.command) {
        case ScriptCommand::Key:
            return {keyEvent(SDL_KEYDOWN, event.key, windowId),
                    keyEvent(SDL_KEYUP, event.key, windowId)};
        case ScriptCommand::KeyDown:
            return {keyEvent(SDL_KEYDOWN, event.key, windowId)};
        case ScriptCommand::KeyUp:
            return {keyEvent(SDL_KEYUP, event.key, windowId)};
        case ScriptCommand::MouseMove:
            return {motionEvent(event.x, event.y, mouse, windowId)};
        case ScriptCommand::MouseDown:
        case ScriptCommand::MouseUp: {
            std::vector<SDL_Event> events;
            if (event.x != mouse.x || event.y != mouse.y) {
                events.push_back(motionEvent(event.x, event.y, mouse, windowId));
            }
            events.push_back(buttonEvent(
                event.command == ScriptCommand::MouseDown ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP,
                event, mouse, windowId));
            return events;
        }
        case ScriptCommand::Click: {
            std::vector<SDL_Event> events;
            if (event.x != mouse.x || event.y != mouse.y) {
                events.push_back(motionEvent(event.x, event.y, mouse, windowId));
            }
            events.push_back(buttonEvent(SDL_MOUSEBUTTONDOWN, event, mouse, windowId));
            events.push_back(buttonEvent(SDL_MOUSEBUTTONUP, event, mouse, windowId));
            return events;
        }
        case ScriptCommand::Wheel: {
            SDL_Event e{};
            e.type = SDL_MOUSEWHEEL;
            e.wheel.windowID = windowId;
            e.wheel.y = event.y;
            e.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
            return {e};
        }
        default:
            return {};
    }
}

}  // namespace luxel::viewer
