// The 2D solver and merge names shared by the CLI and the viewer (luxel/gi2d/solver_choice.h).
#include "luxel/gi2d/solver_choice.h"

#include <gtest/gtest.h>

namespace luxel::gi2d {
namespace {

TEST(SolverChoice, SolverNamesRoundTripAndUnknownNamesAreErrors) {
    for (Solver2D s : {Solver2D::Reference, Solver2D::Hrc, Solver2D::Rc}) {
        auto parsed = parseSolver2D(solverName(s));
        ASSERT_TRUE(parsed.ok()) << solverName(s);
        EXPECT_EQ(*parsed, s);
    }
    auto bad = parseSolver2D("pt");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message(), "--solver 'pt' is not one of: reference, hrc, rc");
    EXPECT_FALSE(parseSolver2D("HRC").ok());
}

TEST(SolverChoice, MergeNamesRoundTripAndFixIsShorthand) {
    for (RcMerge m : {RcMerge::Vanilla, RcMerge::BilinearFix}) {
        auto parsed = parseRcMerge(mergeName(m));
        ASSERT_TRUE(parsed.ok()) << mergeName(m);
        EXPECT_EQ(*parsed, m);
    }
    EXPECT_EQ(*parseRcMerge("fix"), RcMerge::BilinearFix);
    auto bad = parseRcMerge("nearest", "merge");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message(), "merge 'nearest' is not one of: vanilla, bilinear-fix");
}

}  // namespace
}  // namespace luxel::gi2d
