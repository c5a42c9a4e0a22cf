// Every file and section that code and docs point a reader at exists in the repository, and no
// prototype is called by an undefined name.
#include "docs/doc_references.h"

#include <gtest/gtest.h>

#include <string>

#include "support/temp_dir.h"

namespace luxel::docs {
namespace {

std::string describe(const std::vector<ReferenceProblem>& problems) {
    std::string s;
    for (const ReferenceProblem& p : problems) {
        s += p.file + ":" + std::to_string(p.line) + ": " + p.message + "\n";
    }
    return s;
}

TEST(DocReferences, NumberedHeadingsAreSections) {
    const auto sections =
        numberedSections("# Title\n## 1. Model\ntext\n### 6.2 Read-out\n## Notes\n#### 10 Deep\n");
    EXPECT_EQ(sections, (std::vector<std::string>{"1", "6.2", "10"}));
}

TEST(DocReferences, CheckerFindsMissingFilesAndSections) {
    const test::TempDir tree;  // a throw-away source tree for checking the checker
    tree.write("docs/algorithms/cones.md", "# Cones\n## 1. Model\n## 5. Merge\n### 6.2 Read-out\n");
    tree.write("docs/guide.md", "See [the model](algorithms/cones.md) and [gone](missing.md).\n");
    tree.write("src/a.cpp",
               "// docs/algorithms/cones.md §5 and §6.2 are fine\n"
               "// docs/algorithms/cones.md §7 is not\n"
               "// cones.md §1 names no folder\n"
               "// see src/b.cpp and tests/gone_test.cpp\n");
    tree.write("src/b.cpp", "// docs/algorithms/cones.md §1-5, §6.2\n");
    const auto problems = findDanglingReferences(tree.dir());
    ASSERT_EQ(problems.size(), 4u) << describe(problems);
    EXPECT_EQ(problems[0].file, "docs/guide.md");
    EXPECT_NE(problems[0].message.find("missing.md"), std::string::npos);
    EXPECT_EQ(problems[1].line, 2);
    EXPECT_NE(problems[1].message.find("no section 7"), std::string::npos);
    EXPECT_EQ(problems[2].line, 3);
    EXPECT_NE(problems[2].message.find("cones.md does not exist"), std::string::npos);
    EXPECT_EQ(problems[3].line, 4);
    EXPECT_NE(problems[3].message.find("tests/gone_test.cpp"), std::string::npos);
}

TEST(DocReferences, CheckerTellsPrototypeWordingFromRandomSeeds) {
    const test::TempDir tree;  // a throw-away source tree for checking the checker
    tree.write("src/a.cpp",
               "// the seed's controls\n"
               "// as in the vanilla RC seed\n"
               "// PCG32 seeded from (seed, x, y); --seed S; a new seed per pass\n"
               "// ReflectionMode::SeedRunningAverage\n"
               "// options.seed = 3; the RMSE between two seeds\n");
    const auto problems = findUndefinedSeedWording(tree.dir());
    ASSERT_EQ(problems.size(), 3u) << describe(problems);
    EXPECT_EQ(problems[0].line, 1);
    EXPECT_EQ(problems[1].line, 2);
    EXPECT_EQ(problems[2].line, 4);
}

TEST(DocReferences, EveryReferenceInTheRepositoryResolves) {
    const auto problems = findDanglingReferences(LUXEL_SOURCE_DIR);
    EXPECT_TRUE(problems.empty()) << describe(problems);
}

TEST(DocReferences, PrototypesAreNamedByWhatTheyAre) {
    const auto problems = findUndefinedSeedWording(LUXEL_SOURCE_DIR);
    EXPECT_TRUE(problems.empty()) << describe(problems);
}

}  // namespace
}  // namespace luxel::docs
