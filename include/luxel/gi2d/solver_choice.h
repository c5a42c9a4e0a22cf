// The 2D solvers and RC merges by name, parsed in one place so the CLI, the viewer and the
// benches accept the same words and report the same errors.
#pragma once

#include <string_view>

#include "luxel/core/error.h"
#include "luxel/gi2d/rc_solver.h"

namespace luxel::gi2d {

enum class Solver2D {
    Reference,  // brute-force ray marching (reference_solver.h), the ground truth
    Hrc,        // holographic radiance cascades (hrc_solver.h)
    Rc,         // vanilla radiance cascades with a merge (rc_solver.h)
};

// "reference", "hrc" or "rc"; anything else is an error naming `option` and the choices.
Result<Solver2D> parseSolver2D(std::string_view text, std::string_view option = "--solver");
const char* solverName(Solver2D solver);

// "vanilla" or "bilinear-fix" ("fix" is accepted for the latter).
Result<RcMerge> parseRcMerge(std::string_view text, std::string_view option = "--merge");
const char* mergeName(RcMerge merge);

}  // namespace luxel::gi2d
