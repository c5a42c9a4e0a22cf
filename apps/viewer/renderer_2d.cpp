// Scene -> medium -> fluence -> display picture, on the render thread.
#include "renderer_2d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "luxel/core/parallel.h"
#include "luxel/core/timer.h"
#include "luxel/core/tonemap.h"
#include "luxel/gi2d/bounce.h"
#include "luxel/gi2d/display.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rasterize.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gpu/backend_policy.h"
#include "luxel/gpu/context.h"

namespace luxel::viewer {
namespace {

// Edge supersampling for the interactive medium: 4x4 is visually the same as the CLI's 16x16 at
// a fraction of the cost while a shape is being dragged.
constexpr int kSupersample = 4;

gi2d::RcOptions rcOptionsFor(const View2D& view) {
    gi2d::RcOptions options;
    options.merge = view.merge;
    options.debugCascade = view.cascade;
    return options;
}

// Marks the probe centres of the shown cascade (RC layout); when probes are closer than 4 px only
// every k-th is marked so the picture stays visible.
void drawProbes(const View2D& view, Image& picture) {
    const auto cascades = gi2d::rcCascades(picture.width(), picture.height(), rcOptionsFor(view));
    if (cascades.empty()) return;
    const int c = std::clamp(view.cascade, 0, static_cast<int>(cascades.size()) - 1);
    const gi2d::RcCascade& cascade = cascades[static_cast<std::size_t>(c)];
    const int every = std::max(1, static_cast<int>(std::ceil(4.0 / cascade.spacing)));
    for (int py = 0; py < cascade.probesY; py += every) {
        for (int px = 0; px < cascade.probesX; px += every) {
            const int x = static_cast<int>((px + 0.5) * cascade.spacing);
            const int y = static_cast<int>((py + 0.5) * cascade.spacing);
            if (picture.inside(x, y)) picture.setRgb(x, y, Rgb(1.0f, 0.25f, 0.1f));
        }
    }
}

// HRC names its passes per frustum ("trace T0 f2", "upload frame medium 2 (CPU)"); the overlay
// shows each pass summed over the four frustums, so the frustum tokens are dropped.
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

std::string passGroupName(const std::string& name) {
    std::istringstream words(name);
    std::vector<std::string> kept;
    for (std::string w; words >> w;) {
        const bool frustum =
            w.size() >= 2 && w[0] == 'f' && std::all_of(w.begin() + 1, w.end(), isDigit);
        const bool uploadIndex =
            name.rfind("upload frame", 0) == 0 && std::all_of(w.begin(), w.end(), isDigit);
        if (!frustum && !uploadIndex) kept.push_back(w);
    }
    std::string joined;
    for (const std::string& w : kept) joined += (joined.empty() ? "" : " ") + w;
    return joined;
}

// Sums the GPU timings per pass group, in order of first appearance.
std::vector<PassTime> groupTimings(const std::vector<gpu::PassTiming>& timings) {
    std::vector<PassTime> grouped;
    for (const gpu::PassTiming& t : timings) {
        const std::string name = passGroupName(t.name);
        auto it = std::find_if(grouped.begin(), grouped.end(),
                               [&](const PassTime& p) { return p.name == name; });
        if (it == grouped.end()) {
            grouped.push_back({name, t.milliseconds});
        } else {
            it->milliseconds += t.milliseconds;
        }
    }
    return grouped;
}

}  // namespace

int cascadeCount(const View2D& view) {
    switch (view.solver) {
        case gi2d::Solver2D::Hrc:
            return gi2d::hrcCascadeCount(view.width, view.height);
        case gi2d::Solver2D::Rc:
            return static_cast<int>(
                gi2d::rcCascades(view.width, view.height, rcOptionsFor(view)).size());
        case gi2d::Solver2D::Reference:
            return 0;
    }
    return 0;
}

Renderer2D::Renderer2D() = default;
Renderer2D::~Renderer2D() = default;

void Renderer2D::setState(State2D&& state) {
    const View2D& a = state_.view;
    const View2D& b = state.view;
    if (!state_.scene || state.sceneVersion != state_.sceneVersion || a.width != b.width ||
        a.height != b.height) {
        mediumDirty_ = true;
    }
    if (mediumDirty_ || a.solver != b.solver || a.merge != b.merge || a.backend != b.backend ||
        a.gi != b.gi || a.cascade != b.cascade || a.device != b.device || a.bounce != b.bounce ||
        a.bounces != b.bounces || a.rcJitters != b.rcJitters ||
        a.exactNearField != b.exactNearField || a.exactDirectLight != b.exactDirectLight) {
        fluenceDirty_ = true;
    }
    displayDirty_ = true;
    state_ = std::move(state);
}

bool Renderer2D::hasMoreWork() const {
    if (!state_.scene) return false;
    if (mediumDirty_ || fluenceDirty_ || displayDirty_) return true;
    if (bouncing() && bouncesDone_ < state_.view.bounces) return true;
    if (jitteringRc() && rcJittersDone_ < state_.view.rcJitters) return true;
    return state_.view.gi && state_.view.solver == gi2d::Solver2D::Reference &&
           reference_.passes() < referenceTargetPasses_;
}

bool Renderer2D::jitteringRc() const {
    const View2D& v = state_.view;
    return v.gi && v.solver == gi2d::Solver2D::Rc && v.cascade < 0 && v.rcJitters > 1 &&
           !bouncing();
}

bool Renderer2D::bouncing() const {
    const View2D& v = state_.view;
    return v.bounce && v.gi && v.cascade < 0 && v.solver != gi2d::Solver2D::Reference &&
           medium_.bounces();
}

gpu::Context* Renderer2D::gpuFor(const View2D& view) {
    if (view.backend == gpu::Backend::Cpu) return nullptr;
    if (view.solver == gi2d::Solver2D::Reference) {
        note_ = "the reference solver runs on the CPU";
        return nullptr;
    }
    if (view.cascade >= 0) {
        note_ = "the cascade view runs on the CPU";
        return nullptr;
    }
    if (!gpuTried_) {
        gpuTried_ = true;
        auto context = gpu::Context::create({view.device, false});
        if (context) {
            gpu_ = std::move(*context);
        } else {
            gpuError_ = context.error().message();
            std::fprintf(stderr, "luxel-view: note: using the CPU backend (%s)\n",
                         gpuError_.c_str());
        }
    }
    if (!gpu_) {
        note_ = "no Vulkan device (" + gpuError_ + "); using the CPU";
        return nullptr;
    }
    // The backend policy (luxel/gpu/backend_policy.h): auto skips software devices.
    if (view.backend == gpu::Backend::Auto && !gpu::autoUsesDevice(gpu_->device())) {
        note_ = "auto: skipped the software Vulkan device " + gpu_->device().name;
        return nullptr;
    }
    return gpu_.get();
}

Status Renderer2D::solve(Frame& frame) {
    const View2D& view = state_.view;
    const int w = medium_.width(), h = medium_.height();
    if (!view.gi) {
        fluence_ = Image(w, h, 3);
        frame.note = "GI off: emission only";
        return Ok{};
    }
    gpu::Context* gpu = gpuFor(view);
    frame.backend = gpu ? "gpu" : "cpu";
    frame.device =
        gpu ? gpu->device().name : "CPU, " + std::to_string(hardwareThreads()) + " threads";
    Stopwatch clock;
    std::vector<gpu::PassTiming> timings;
    Result<Image> fluence = Image();
    const gi2d::Medium2D& medium = bouncing() ? lit_ : medium_;
    switch (view.solver) {
        case gi2d::Solver2D::Hrc: {
            gi2d::HrcOptions options;
            options.debugCascade = view.cascade;
            options.exactNearField = view.exactNearField;
            options.exactDirectLight = view.exactDirectLight;
            fluence = gpu ? gi2d::solveHrcOnGpu(*gpu, medium, options, &timings)
                          : gi2d::solveHrc(medium, options);
            break;
        }
        case gi2d::Solver2D::Rc: {
            gi2d::RcOptions options = rcOptionsFor(view);
            const bool jitter = jitteringRc();
            if (jitter) gi2d::rcJitterShift(rcJittersDone_, options.jitterX, options.jitterY);
            fluence = gpu ? gi2d::solveRcOnGpu(*gpu, medium, options, &timings)
                          : gi2d::solveRc(medium, options);
            if (!jitter || !fluence) break;
            // The running mean of the jittered grids since the last change.
            if (rcJittersDone_ == 0) {
                rcSum_ = *fluence;
            } else {
                for (std::size_t i = 0; i < rcSum_.size(); ++i) {
                    rcSum_.data()[i] += fluence->data()[i];
                }
            }
            ++rcJittersDone_;
            const float scale = 1.0f / static_cast<float>(rcJittersDone_);
            for (std::size_t i = 0; i < fluence->size(); ++i) {
                fluence->data()[i] = rcSum_.data()[i] * scale;
            }
            frame.note = "probe grids " + std::to_string(rcJittersDone_) + "/" +
                         std::to_string(view.rcJitters);
            break;
        }
        case gi2d::Solver2D::Reference: {
            if (Status s = reference_.addPass(medium_); !s) return s;
            fluence = reference_.mean();
            frame.samples = reference_.raysPerPixel();
            frame.converged = reference_.passes() >= referenceTargetPasses_;
            break;
        }
    }
    if (!fluence) return fluence.error();
    fluence_ = std::move(*fluence);
    if (!timings.empty()) {
        frame.passes = groupTimings(timings);
    } else {
        frame.passes.push_back({gi2d::solverName(view.solver), clock.milliseconds()});
    }
    return Ok{};
}

Frame Renderer2D::step() {
    Stopwatch total;
    const View2D& view = state_.view;
    Frame frame;
    note_.clear();
    if (mediumDirty_) {
        Stopwatch clock;
        const gi2d::RasterOptions raster{view.width, view.height, kSupersample};
        auto medium = gi2d::rasterize(*state_.scene, raster);
        mediumDirty_ = false;
        if (!medium) {
            frame.note = medium.error().message();
            displayDirty_ = fluenceDirty_ = false;
            return frame;
        }
        medium_ = std::move(*medium);
        reference_.reset();
        last_.passes.clear();
        last_.passes.push_back({"raster", clock.milliseconds()});
    }
    const bool refining = view.gi && view.solver == gi2d::Solver2D::Reference &&
                          reference_.passes() < referenceTargetPasses_;
    // One bounce per frame: the last frame's fluence lights the next frame's source.
    const bool bounceNow = !fluenceDirty_ && bouncing() && bouncesDone_ < view.bounces;
    // One more jittered RC probe grid per frame until View2D::rcJitters.
    const bool jitterNow = !fluenceDirty_ && jitteringRc() && rcJittersDone_ < view.rcJitters;
    if (fluenceDirty_) rcJittersDone_ = 0;
    if (fluenceDirty_ && bouncing()) {
        lit_ = medium_;
        bouncesDone_ = 0;
    } else if (bounceNow) {
        lit_.emission = gi2d::bounceSource(medium_, fluence_, lit_.emission);
        ++bouncesDone_;
    }
    if (fluenceDirty_ || refining || bounceNow || jitterNow) {
        if (fluenceDirty_) reference_.reset();
        fluenceDirty_ = false;
        Frame solved;
        if (Status s = solve(solved); !s) {
            solved.note = std::string(gi2d::solverName(view.solver)) + ": " + s.error().message();
            fluence_ = Image(medium_.width(), medium_.height(), 3);
            reference_ = ProgressiveReference();
            referenceTargetPasses_ = 0;  // stop refining a failing solve
        } else if (view.solver == gi2d::Solver2D::Reference) {
            referenceTargetPasses_ = 256;
        }
        if (!note_.empty()) solved.note = solved.note.empty() ? note_ : note_ + "; " + solved.note;
        if (bouncing()) {
            solved.note += (solved.note.empty() ? "" : "; ") + std::string("bounce ") +
                           std::to_string(bouncesDone_) + "/" + std::to_string(view.bounces);
        }
        std::vector<PassTime> passes;
        for (const PassTime& p : last_.passes) {
            if (p.name == "raster") passes.push_back(p);
        }
        passes.insert(passes.end(), solved.passes.begin(), solved.passes.end());
        solved.passes = std::move(passes);
        last_ = std::move(solved);
    }
    displayDirty_ = false;
    Stopwatch displayClock;
    Image picture = gi2d::displayImage(medium_, fluence_, {view.exposure, ToneCurve::Aces});
    if (view.probes) drawProbes(view, picture);
    frame = last_;
    frame.picture = std::move(picture);
    frame.passes.push_back({"display", displayClock.milliseconds()});
    frame.renderMilliseconds = total.milliseconds();
    if (frame.backend.empty()) frame.backend = "cpu";
    return frame;
}

}  // namespace luxel::viewer
