// What a renderer hands to the window: a display-ready picture plus what the overlay reports.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "luxel/core/image.h"
#include "luxel/core/image_metadata.h"

namespace luxel::viewer {

struct PassTime {
    std::string name;
    double milliseconds = 0.0;
};

struct Frame {
    Image picture;                 // linear [0, 1] RGB at the internal resolution (tone mapped)
    std::uint64_t generation = 0;  // the state it shows (see RenderWorker)
    bool converged = true;         // false while a progressive render is still refining it
    int samples = 0;               // progressive passes accumulated (0 when not progressive)
    // A later pass of a progressive render of an unchanged view: its time says nothing about
    // the interactive rate (adaptive_resolution.h ignores it).
    bool accumulating = false;
    // The path tracer's relative standard error of the mean (NaN: not known).
    double relativeError = std::numeric_limits<double>::quiet_NaN();
    double renderMilliseconds = 0.0;  // wall time of the step that produced it
    std::vector<PassTime> passes;     // per pass; GPU timestamps on the GPU backend
    std::string backend;              // "cpu" or "gpu"
    std::string device;               // CPU threads or the Vulkan device name
    std::string note;                 // one line for the overlay (fallbacks, errors)
    ImageMetadata metadata;           // written into screenshots (solver, samples, ...)
};

}  // namespace luxel::viewer
