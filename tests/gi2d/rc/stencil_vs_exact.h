// The stencil-walk RC pass (src/gi2d/rc/rc_stencil.h) against the exact pass it replaces
// (cascadePass over RayMarcher), shared by the stencil tests and the uniform-square tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gi2d/rc/rc_cascade_pass.h"
#include "gi2d/rc/rc_stencil.h"
#include "luxel/gi2d/ray_march.h"
#include "luxel/gi2d/rc_solver.h"

namespace luxel::gi2d::rc {

// Every cascade of both merges, top-down, each level fed the exact upper cascade: each value
// within 2e-5 of the mean (or of itself where it is far brighter: a dark top cascade's few bright
// values differ by their own rounding) and the relative L1 within 1e-6. `label` names the case.
inline void expectStencilMatchesExact(const Medium2D& medium, const RcOptions& options,
                                      const std::string& label) {
    const RayMarcher marcher(medium);
    const StencilMedium stencilMedium(medium);
    const std::vector<RcCascade> cascades = rcCascades(medium.width(), medium.height(), options);
    for (RcMerge merge : {RcMerge::Vanilla, RcMerge::BilinearFix}) {
        std::vector<Rgb> upper;
        for (int i = static_cast<int>(cascades.size()) - 1; i >= 0; --i) {
            const std::vector<Rgb> exact =
                cascadePass(marcher, cascades, i, upper, medium.boundaryRadiance, merge);
            const int upStored = i + 1 < static_cast<int>(cascades.size())
                                     ? storedPerProbe(cascades[i + 1], i + 1)
                                     : 1;
            const std::vector<Rgb> fast = toProbeMajor(
                cascadePassStencil(marcher, stencilMedium, cascades, i,
                                   toSlotMajor(upper, upStored), medium.boundaryRadiance, merge),
                storedPerProbe(cascades[i], i));
            ASSERT_EQ(exact.size(), fast.size());
            double sumRef = 0, sumAbs = 0;
            for (std::size_t v = 0; v < exact.size(); ++v) {
                for (int c = 0; c < 3; ++c) {
                    sumRef += std::abs(exact[v][c]);
                    sumAbs += std::abs(fast[v][c] - exact[v][c]);
                }
            }
            const double mean = sumRef / (3.0 * exact.size());
            double worst = 0;
            for (std::size_t v = 0; v < exact.size(); ++v) {
                for (int c = 0; c < 3; ++c) {
                    worst = std::max(
                        worst, std::abs(fast[v][c] - exact[v][c]) / (mean + std::abs(exact[v][c])));
                }
            }
            const std::string what = label + ", " +
                                     (merge == RcMerge::Vanilla ? "vanilla" : "fix") +
                                     ", cascade " + std::to_string(i);
            std::printf("%s: max diff %.2e, relative L1 %.2e\n", what.c_str(), worst,
                        sumAbs / sumRef);
            EXPECT_LT(worst, 2e-5) << what;
            EXPECT_LE(sumAbs, 1e-6 * sumRef) << what;
            upper = exact;
        }
    }
}

}  // namespace luxel::gi2d::rc
