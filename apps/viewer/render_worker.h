// Runs a renderer on its own thread so the window never waits for a frame: the app posts states
// (cheap snapshots) and shows the latest finished frame. States posted while the renderer is busy
// are all handed over, in order, before its next step, so edits carried by states are never lost,
// while the picture is only rendered for the newest one.
//
// Renderer requirements (duck-typed):
//   using State = ...;                 // copyable snapshot of what to draw
//   void setState(State&& state);      // called on the worker thread, in posting order
//   bool hasMoreWork() const;          // e.g. progressive refinement pending
//   Frame step();                      // renders (or refines) the current state
#pragma once

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "frame.h"

namespace luxel::viewer {

template <typename Renderer>
class RenderWorker {
  public:
    using State = typename Renderer::State;

    explicit RenderWorker(std::unique_ptr<Renderer> renderer)
        : renderer_(std::move(renderer)), thread_([this] { run(); }) {}
    ~RenderWorker() {
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    // Queues a state; `generation` must grow with every post.
    void post(State state, std::uint64_t generation) {
        {
            std::lock_guard lock(mutex_);
            pending_.push_back(std::move(state));
            postedGeneration_ = generation;
        }
        wake_.notify_all();
    }

    // The newest finished frame, or nullptr before the first. With `fresh`, says whether it
    // arrived since the previous call that asked.
    std::shared_ptr<const Frame> latest(bool* fresh = nullptr) {
        std::lock_guard lock(mutex_);
        if (fresh) {
            *fresh = latestSerial_ != takenSerial_;
            takenSerial_ = latestSerial_;
        }
        return latest_;
    }

  private:
    void run() {
        std::uint64_t generation = 0;
        for (;;) {
            std::vector<State> states;
            {
                std::unique_lock lock(mutex_);
                wake_.wait(lock,
                           [&] { return stop_ || !pending_.empty() || renderer_->hasMoreWork(); });
                if (stop_) return;
                states.swap(pending_);
                generation = postedGeneration_;
            }
            for (State& s : states) renderer_->setState(std::move(s));
            auto frame = std::make_shared<Frame>(renderer_->step());
            frame->generation = generation;
            std::lock_guard lock(mutex_);
            latest_ = std::move(frame);
            ++latestSerial_;
        }
    }

    std::unique_ptr<Renderer> renderer_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::vector<State> pending_;
    std::uint64_t postedGeneration_ = 0;
    std::shared_ptr<const Frame> latest_;
    std::uint64_t latestSerial_ = 0, takenSerial_ = 0;
    bool stop_ = false;
    std::thread thread_;  // last: starts after every other member exists
};

}  // namespace luxel::viewer
