// The 2D solve of `luxel render` (render_solve_2d.cpp): the chosen solver with bounce light.
#pragma once

#include <string>

#include "commands/command.h"
#include "commands/render_args.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/rc_solver.h"

namespace luxel::cli {

// The RC options a render's arguments ask for (also what --view probes draws).
gi2d::RcOptions rcOptions(const RenderArgs& args);

// The chosen solver with bounce light fed back (gi2d/bounce.h) when the medium bounces: the
// reference converges unless --bounces caps it, HRC and RC run --bounces (default
// kDefaultCascadeBounces) extra solves. `note` says what happened, for the summary line.
Result<Image> solveBouncing(const RenderArgs& args, const SizedScene& sized,
                            const gi2d::Medium2D& medium, double& rays, std::string& detail,
                            std::string& note);

}  // namespace luxel::cli
