// Built-in sin/asin against polynomial versions (shared/trig_approx.h), for timing on the device:
// each invocation evaluates the function `iterations` times on a moving argument and stores the
// sum, so nothing can be hoisted out of the loop. CPU twin of the values: bench/bench_trig.cpp.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/post_layout.h"
#include "shared/trig_approx.h"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Inputs { float inputs[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Outputs { float outputs[]; };
layout(push_constant) uniform Push { PostTrigParams params; };

float evaluate(float x) {
    switch (params.function) {
        case 0u: return sin(x);
        case 1u: return taylorSin(x, int(params.terms));
        case 2u: return asin(x);
        case 3u: return taylorAsin(x, int(params.terms));
        default: return minimaxAsin8(x);
    }
}

void main() {
    const uint i = LUXEL_LINEAR_INVOCATION;
    if (i >= params.count) return;
    const float x = inputs[i];
    float sum = 0.0;
    for (uint k = 0u; k < params.iterations; ++k) {
        sum += evaluate(x * (1.0 - float(k) * 1e-7));
    }
    outputs[i] = params.iterations == 1u ? evaluate(x) : sum;
}
