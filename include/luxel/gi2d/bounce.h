// Light that bounces (docs/algorithms/scattering-2d.md): one rule, shared by every 2D solver, that
// turns a medium and the fluence it produced into the emission of the next solve, and a driver
// that feeds fluence back until the emission stops changing (or for a fixed number of bounces).
#pragma once

#include <functional>

#include "luxel/core/error.h"
#include "luxel/core/image.h"
#include "luxel/gi2d/medium2d.h"
#include "luxel/gi2d/reference_solver.h"

namespace luxel::gi2d {

// The source radiance S_next for the next solve:
//  - every pixel: S = E + scattering * fluence (isotropic scattering, fluence = mean radiance);
//  - pixels with reflectance rho > 0 also add rho * I, where I, the mean radiance arriving from
//    outside, is estimated from the transparent neighbours q as max(0, 2 fluence_q - S_prev(p)).
// `previousSource` is the emission the fluence was solved with (medium.emission at first).
Image bounceSource(const Medium2D& medium, const Image& fluence, const Image& previousSource);

struct BounceOptions {
    int maxBounces = 0;  // fluence fed back at most this many times (0: one plain solve)
    // > 0: stop once the bounced light (source minus emission) changes by less than this,
    // relative L1, in one bounce (converged).
    double tolerance = 0.0;
    // Called after each solve with (solves so far, relative change of the source that was used).
    std::function<void(int solve, double change)> onSolve;
};

struct BounceResult {
    Image fluence;
    Image source;            // the emission of the last solve (E plus bounced light)
    int bounces = 0;         // times the fluence was fed back
    bool converged = false;  // the tolerance was met (false for a fixed count)
    double change = 0.0;     // relative change of the bounced light in the last bounce
};

using FluenceSolve = std::function<Result<Image>(const Medium2D&)>;

// Solves with S_0 = E, then S_{k+1} = bounceSource(medium, fluence_k, S_k), re-solving each time.
// For a medium that does not bounce this is one solve.
Result<BounceResult> solveWithBounces(const Medium2D& medium, const FluenceSolve& solve,
                                      const BounceOptions& options);

// Bounces a solver runs by default when the scene bounces: the reference converges (up to
// kMaxReferenceBounces at kReferenceTolerance), cascades feed back kDefaultCascadeBounces times.
inline constexpr int kMaxReferenceBounces = 200;
inline constexpr double kReferenceTolerance = 1e-3;
inline constexpr int kDefaultCascadeBounces = 16;

// The reference solver fed back until the bounced light changes by less than `tolerance` (at most
// kMaxReferenceBounces solves); BounceResult::converged says whether it got there.
Result<BounceResult> solveReferenceWithBounces(const Medium2D& medium,
                                               const ReferenceOptions& reference,
                                               double tolerance = kReferenceTolerance);

}  // namespace luxel::gi2d
