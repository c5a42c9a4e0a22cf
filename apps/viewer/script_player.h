// Plays a Script one frame at a time: each frame the app asks which events are due, given the
// clock and whether the picture is up to date, and dispatches them like real input. Pure logic.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "input_script.h"

namespace luxel::viewer {

struct ScriptClock {
    double seconds = 0.0;          // since the viewer started
    bool renderCurrent = false;    // the shown frame was rendered from the current state
    bool renderConverged = false;  // ... and no refinement (reference accumulation) is pending
};

class ScriptPlayer {
  public:
    // A wait (wait, wait_render, ...) that is not over after `waitTimeoutSeconds` is an error.
    explicit ScriptPlayer(Script script, double waitTimeoutSeconds = 120.0);

    // The events to dispatch this frame, in order; waits are consumed here, never returned.
    // Call once per frame.
    std::vector<ScriptEvent> due(const ScriptClock& clock);

    bool finished() const { return next_ >= script_.events.size(); }
    // Set when a wait timed out: "FILE:LINE: wait_render: not done after 120 s".
    const std::optional<std::string>& failure() const { return failure_; }

  private:
    bool waitOver(const ScriptEvent& event, const ScriptClock& clock);

    Script script_;
    double timeout_;
    std::size_t next_ = 0;
    long long frame_ = 0;
    // Start of the current wait (time and frame), set when the wait is first seen.
    bool waiting_ = false;
    double waitStartSeconds_ = 0.0;
    long long waitStartFrame_ = 0;
    std::optional<std::string> failure_;
};

}  // namespace luxel::viewer
