// Which pixels emit, for the compact lights' search
// (docs/algorithms/holographic-radiance-cascades.md §12.5): E (1 - exp(-sigma)) > 0 in some
// channel, told a row at a time with Highway vectors without exponentials wherever the answer is
// sure, as in all of a canvas but a few pixels.
#pragma once

#include <cstdint>

namespace luxel::gi2d::hrc {

// A pixel surely emits where some channel has E >= kSureEmission and sigma >= kSureAbsorption:
// exp(-sigma) is then below 1 by at least 16 float steps, so E (1 - exp(-sigma)) is a normal
// positive float, whatever the exponential's rounding.
inline constexpr float kSureEmission = 1e-30f;
inline constexpr float kSureAbsorption = 1e-6f;

// For the `width` RGB pixels of a row: state[x] = 1 where the pixel surely emits, 2 where E and
// sigma of some channel have one sign but it is not sure (the exponentials tell), 0 where no
// channel's do (then E (1 - exp(-sigma)) is not above 0 in any, NaN included). Returns how many
// are 2.
int emittingRow(const float* emission, const float* sigma, int width, std::uint8_t* state);

}  // namespace luxel::gi2d::hrc
