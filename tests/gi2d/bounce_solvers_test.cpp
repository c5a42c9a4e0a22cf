// Multibounce HRC and RC (fluence fed back through the shared bounce rule) against the converged
// scattering reference.
#include <gtest/gtest.h>

#include <cstdio>

#include "bounce_media.h"
#include "luxel/gi2d/bounce.h"
#include "luxel/gi2d/hrc_solver.h"
#include "luxel/gi2d/rc_solver.h"
#include "luxel/gi2d/reference_solver.h"

namespace luxel::gi2d {
namespace {

Image convergedReference(const Medium2D& medium) {
    ReferenceOptions ref;
    ref.rays = 256;
    auto r = solveReferenceWithBounces(medium, ref);
    EXPECT_TRUE(r.ok());
    EXPECT_TRUE(r->converged);
    return std::move(r->fluence);
}

Image bounced(const Medium2D& medium, const FluenceSolve& solve, int bounces) {
    BounceOptions options;
    options.maxBounces = bounces;
    auto r = solveWithBounces(medium, solve, options);
    EXPECT_TRUE(r.ok());
    return std::move(r->fluence);
}

// The fog reference is shared by the HRC and RC tests (it is the slow part).
const Image& fogReference() {
    static const Image reference = convergedReference(test::fogScene());
    return reference;
}

void expectHrcClose(const char* name, const Medium2D& medium, const Image& reference) {
    const FluenceSolve hrc = [](const Medium2D& m) { return solveHrc(m); };
    const double noBounce = test::relativeL1(bounced(medium, hrc, 0), reference);
    const double multi = test::relativeL1(bounced(medium, hrc, kDefaultCascadeBounces), reference);
    std::printf(
        "%s: hrc rel-L1 against the converged reference: %.4f without bounces, %.4f with "
        "%d\n",
        name, noBounce, multi, kDefaultCascadeBounces);
    EXPECT_GT(noBounce, 0.1);  // bounce light matters in these scenes
    EXPECT_LT(multi, 0.03);
}

TEST(BounceSolvers, MultibounceHrcMatchesReferenceInFog) {
    expectHrcClose("fog", test::fogScene(), fogReference());
}

TEST(BounceSolvers, MultibounceHrcMatchesReferenceInReflectiveRoom) {
    const Medium2D room = test::reflectiveRoom();
    expectHrcClose("room", room, convergedReference(room));
}

// RC is less accurate than HRC on its own; bouncing must not make it worse than it is without
// bounce light, measured on the same scattering problem.
TEST(BounceSolvers, MultibounceRcApproachesReference) {
    const Medium2D medium = test::fogScene();
    const Image& reference = fogReference();
    const FluenceSolve rc = [](const Medium2D& m) { return solveRc(m); };
    const double noBounce = test::relativeL1(bounced(medium, rc, 0), reference);
    const double multi = test::relativeL1(bounced(medium, rc, kDefaultCascadeBounces), reference);
    std::printf("fog: rc rel-L1 %.4f without bounces, %.4f with %d\n", noBounce, multi,
                kDefaultCascadeBounces);
    EXPECT_LT(multi, 0.5 * noBounce);
}

}  // namespace
}  // namespace luxel::gi2d
