// Polynomial sin and asin for the Taylor-versus-built-in measurement
// (docs/algorithms/trig-approximations.md): truncated Taylor series about 0 and the minimax
// asin fits of Abramowitz & Stegun, Handbook of Mathematical Functions (1964), 4.4.45 and 4.4.46
// (after Hastings 1955), which have the form Lagarde uses on GCN: pi/2 - sqrt(1 - |x|) P(|x|).
// Compiled as C++ by bench/bench_trig.cpp and tests, as GLSL by post_trig_timing.
#ifndef LUXEL_GPU_SHARED_TRIG_APPROX_H
#define LUXEL_GPU_SHARED_TRIG_APPROX_H

#include "glsl_compat.h"

LUXEL_SHARED_BEGIN

// sin x ~ sum_{n < terms} (-1)^n x^(2n+1) / (2n+1)!, no range reduction.
LUXEL_FUNC float taylorSin(float x, int terms) {
    const float x2 = x * x;
    float term = x;
    float sum = x;
    for (int n = 1; n < terms; ++n) {
        term *= -x2 / (float(2 * n) * float(2 * n + 1));
        sum += term;
    }
    return sum;
}

// asin x ~ sum_{n < terms} a_n x^(2n+1), a_0 = 1, a_{n+1} = a_n (2n+1)^2 / ((2n+2)(2n+3)).
LUXEL_FUNC float taylorAsin(float x, int terms) {
    const float x2 = x * x;
    float power = x;
    float coefficient = 1.0f;
    float sum = x;
    for (int n = 0; n + 1 < terms; ++n) {
        coefficient *= float((2 * n + 1) * (2 * n + 1)) / float((2 * n + 2) * (2 * n + 3));
        power *= x2;
        sum += coefficient * power;
    }
    return sum;
}

// A&S 4.4.45: |error| <= 5e-5 on [-1, 1] (4 coefficients).
LUXEL_FUNC float minimaxAsin4(float x) {
    const float a = abs(x);
    const float p = 1.5707288f + a * (-0.2121144f + a * (0.0742610f + a * -0.0187293f));
    const float r = 1.5707963268f - sqrt(1.0f - a) * p;
    return x < 0.0f ? -r : r;
}

// A&S 4.4.46: |error| <= 2e-8 on [-1, 1] (8 coefficients; float rounding dominates).
LUXEL_FUNC float minimaxAsin8(float x) {
    const float a = abs(x);
    const float p =
        1.5707963050f +
        a * (-0.2145988016f +
             a * (0.0889789874f +
                  a * (-0.0501743046f +
                       a * (0.0308918810f +
                            a * (-0.0170881256f + a * (0.0066700901f + a * -0.0012624911f))))));
    const float r = 1.5707963268f - sqrt(1.0f - a) * p;
    return x < 0.0f ? -r : r;
}

LUXEL_SHARED_END

#endif
