// Checks that every file and section a reader is pointed at exists: Markdown links, `*.md`
// mentions, repository paths such as `src/voxel/dda.cpp`, and `§N` section numbers after a
// Markdown file (which must match a numbered heading "## N." / "### N.M" in that file).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace luxel::docs {

struct ReferenceProblem {
    std::string file;  // relative to the scanned root
    int line = 0;
    std::string message;
};

// The numbered headings of a Markdown text: "## 5. Title" -> "5", "### 6.2 Title" -> "6.2".
std::vector<std::string> numberedSections(const std::string& markdown);

// Scans the C++/GLSL/CMake/Markdown/shell files under `root` (skipping build output and hidden
// folders) and returns every reference that does not resolve, in path and line order.
std::vector<ReferenceProblem> findDanglingReferences(const std::filesystem::path& root);

// Lines that use "seed" as the name of a prototype rather than for a random-number seed;
// docs/prototypes.md names each prototype by what it is.
std::vector<ReferenceProblem> findUndefinedSeedWording(const std::filesystem::path& root);

}  // namespace luxel::docs
