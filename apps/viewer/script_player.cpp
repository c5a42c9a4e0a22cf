// Frame-by-frame playback of a Script.
#include "script_player.h"

#include <utility>

namespace luxel::viewer {

ScriptPlayer::ScriptPlayer(Script script, double waitTimeoutSeconds)
    : script_(std::move(script)), timeout_(waitTimeoutSeconds) {}

bool ScriptPlayer::waitOver(const ScriptEvent& event, const ScriptClock& clock) {
    if (!waiting_) {
        waiting_ = true;
        waitStartSeconds_ = clock.seconds;
        waitStartFrame_ = frame_;
    }
    const double waited = clock.seconds - waitStartSeconds_;
    bool over = true;
    if (event.at >= 0 && clock.seconds < event.at) over = false;
    switch (event.command) {
        case ScriptCommand::Wait:
            if (waited < event.seconds) over = false;
            break;
        case ScriptCommand::WaitFrames:
            if (frame_ - waitStartFrame_ < event.frames) over = false;
            break;
        case ScriptCommand::WaitRender:
            if (!clock.renderCurrent) over = false;
            break;
        case ScriptCommand::WaitConverged:
            if (!clock.renderCurrent || !clock.renderConverged) over = false;
            break;
        default:
            break;
    }
    if (!over && waited > timeout_ && event.command != ScriptCommand::Wait && event.at < 0) {
        failure_ = script_.name + ":" + std::to_string(event.line) + ": wait did not end within " +
                   std::to_string(static_cast<int>(timeout_)) + " s";
    }
    if (over) waiting_ = false;
    return over;
}

std::vector<ScriptEvent> ScriptPlayer::due(const ScriptClock& clock) {
    std::vector<ScriptEvent> events;
    while (!finished() && !failure_) {
        const ScriptEvent& event = script_.events[next_];
        // The clock was read before this frame's events ran: a render wait after them must look
        // at the next frame's clock, which knows about the state they changed.
        const bool renderWait = event.command == ScriptCommand::WaitRender ||
                                event.command == ScriptCommand::WaitConverged;
        if (renderWait && !events.empty()) break;
        if (!waitOver(event, clock)) break;
        const bool isWait = event.command == ScriptCommand::Wait ||
                            event.command == ScriptCommand::WaitFrames ||
                            event.command == ScriptCommand::WaitRender ||
                            event.command == ScriptCommand::WaitConverged;
        if (!isWait) events.push_back(event);
        ++next_;
        // A screenshot shows the state left by the events before it only after a frame has
        // been drawn, so it ends this frame's batch.
        if (event.command == ScriptCommand::Screenshot ||
            event.command == ScriptCommand::ScreenshotWindow) {
            break;
        }
    }
    ++frame_;
    return events;
}

}  // namespace luxel::viewer
