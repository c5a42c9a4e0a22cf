// Numeric option checks shared by the luxel and luxel-view command lines. CLI::Range on a float
// lets "nan" through (every comparison with NaN is false), so float options use finiteIn;
// whole-number options use wholeIn. Both parse the whole text with std::from_chars, so overflow
// and trailing characters are refused too.
#pragma once

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace luxel::options {

// "%g" of a bound, as the messages print it.
inline std::string boundText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// A finite number in [lo, hi].
inline CLI::Validator finiteIn(double lo, double hi) {
    const std::string range = "[" + boundText(lo) + ", " + boundText(hi) + "]";
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            double v = 0;
            const char* end = text.data() + text.size();
            const auto [stop, ec] = std::from_chars(text.data(), end, v);
            if (ec != std::errc{} || stop != end || !std::isfinite(v) || v < lo || v > hi) {
                return "'" + text + "' is not a finite number in " + range;
            }
            return {};
        },
        "FLOAT in " + range);
}

// A whole number in lo..hi.
inline CLI::Validator wholeIn(long long lo, long long hi) {
    const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            long long v = 0;
            const char* end = text.data() + text.size();
            const auto [stop, ec] = std::from_chars(text.data(), end, v);
            if (ec != std::errc{} || stop != end || v < lo || v > hi) {
                return "'" + text + "' is not a whole number in " + range;
            }
            return {};
        },
        "INT in " + range);
}

}  // namespace luxel::options
