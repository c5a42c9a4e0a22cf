#include "docs/doc_references.h"

#include <algorithm>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>

namespace luxel::docs {
namespace fs = std::filesystem;
namespace {

// Top-level folders whose paths code and docs cite as `folder/.../file.ext`.
const std::regex kRepoPath(
    R"(\b((?:src|include|tests|docs|apps|bench|tools|scripts|scenes|fuzz|cmake|deps)/[A-Za-z0-9_./-]*[A-Za-z0-9_]\.(?:h|cpp|glsl|md|json|txt|sh|vox|cmake|py|png))\b)");
// Any Markdown file name, with or without folders.
const std::regex kMarkdownName(R"(([A-Za-z0-9_./-]*[A-Za-z0-9_-]\.md)\b)");
// A Markdown link with its text, and the target alone: ](target) or ](target#anchor).
const std::regex kLinkWithText(R"(\[[^\]]*\]\(([^)]*)\))");
const std::regex kMarkdownLink(R"(\]\(([^)#\s]*)(?:#[^)\s]*)?\))");
// Section numbers following a file name: "§5", "§3-4", "§10, §13", "§6.2".
const std::regex kSection(R"(^\)?`?\s*§\s?(\d+(?:\.\d+)*)(?:\s*[-–]\s*§?(\d+(?:\.\d+)*))?)");
const std::regex kMoreSections(R"(^\s*(?:,|and)\s*§\s?(\d+(?:\.\d+)*))");

bool scanned(const fs::path& p) {
    static const std::vector<std::string> exts{".h",   ".cpp",   ".glsl", ".md",
                                               ".txt", ".cmake", ".sh",   ".py"};
    const std::string name = p.filename().string();
    return std::find(exts.begin(), exts.end(), p.extension().string()) != exts.end() ||
           name == "Makefile" || name == "run";
}

std::vector<fs::path> filesUnder(const fs::path& root) {
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
         ++it) {
        const std::string name = it->path().filename().string();
        if (it->is_directory() && (name.starts_with(".") || name == "build" || name == "out") &&
            name != ".ci") {
            it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file() && scanned(it->path())) files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<std::string> readLines(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string readText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// A reference resolves against the repository root or the citing file's folder.
std::optional<fs::path> resolve(const fs::path& root, const fs::path& citing,
                                const std::string& target) {
    for (const fs::path& base : {root, citing.parent_path()}) {
        const fs::path candidate = (base / target).lexically_normal();
        if (fs::is_regular_file(candidate)) return candidate;
    }
    return std::nullopt;
}

void checkSections(const fs::path& markdown, const std::string& rest, const std::string& name,
                   std::vector<std::string>& problems) {
    std::smatch m;
    if (!std::regex_search(rest, m, kSection)) return;
    const std::vector<std::string> have = numberedSections(readText(markdown));
    std::vector<std::string> wanted{m[1].str()};
    if (m[2].matched) wanted.push_back(m[2].str());
    std::string tail = m.suffix().str();
    while (std::regex_search(tail, m, kMoreSections)) {
        wanted.push_back(m[1].str());
        tail = m.suffix().str();
    }
    for (const std::string& section : wanted) {
        if (std::find(have.begin(), have.end(), section) == have.end()) {
            problems.push_back(name + " has no section " + section);
        }
    }
}

// Calls body(file, path relative to root, 1-based line number, line) for every line of the
// scanned files, except the checker's own (its patterns and fixtures name missing files on
// purpose).
template <typename Body>
void forEachScannedLine(const fs::path& root, Body&& body) {
    for (const fs::path& file : filesUnder(root)) {
        const std::string rel = fs::relative(file, root).generic_string();
        if (rel.starts_with("tests/docs/doc_references")) continue;
        const std::vector<std::string> lines = readLines(file);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            body(file, rel, static_cast<int>(i + 1), lines[i]);
        }
    }
}

}  // namespace

std::vector<std::string> numberedSections(const std::string& markdown) {
    static const std::regex heading(R"(^#{2,4}\s+(\d+(?:\.\d+)*)\.?\s)");
    std::vector<std::string> sections;
    std::istringstream in(markdown);
    for (std::string line; std::getline(in, line);) {
        std::smatch m;
        if (std::regex_search(line, m, heading)) sections.push_back(m[1].str());
    }
    return sections;
}

std::vector<ReferenceProblem> findDanglingReferences(const fs::path& root) {
    std::vector<ReferenceProblem> out;
    forEachScannedLine(root, [&](const fs::path& file, const std::string& rel, int lineNumber,
                                 const std::string& text) {
        if (text.starts_with("#include")) return;  // include paths, checked by the build
        // Markdown links read as their targets ("[cones](algorithms/cones.md) §4" cites
        // algorithms/cones.md §4); the link text is not a reference of its own.
        const std::string line =
            file.extension() == ".md" ? std::regex_replace(text, kLinkWithText, "($1)") : text;
        std::vector<std::string> problems;
        auto check = [&](const std::string& target, std::size_t end) {
            if (target.find("://") != std::string::npos || target.empty()) return;
            auto found = resolve(root, file, target);
            if (!found) {
                problems.push_back(target + " does not exist in the repository");
            } else if (found->extension() == ".md") {
                checkSections(*found, line.substr(end), target, problems);
            }
        };
        for (auto it = std::sregex_iterator(line.begin(), line.end(), kMarkdownName);
             it != std::sregex_iterator(); ++it) {
            const std::size_t end = static_cast<std::size_t>(it->position(1) + it->length(1));
            check((*it)[1].str(), end);
        }
        for (auto it = std::sregex_iterator(line.begin(), line.end(), kRepoPath);
             it != std::sregex_iterator(); ++it) {
            const std::string target = (*it)[1].str();
            const bool absolute = it->position(1) > 0 && line[it->position(1) - 1] == '/';
            if (!target.ends_with(".md") && !absolute) check(target, line.size());
        }
        if (file.extension() == ".md") {
            for (auto it = std::sregex_iterator(text.begin(), text.end(), kMarkdownLink);
                 it != std::sregex_iterator(); ++it) {
                const std::string target = (*it)[1].str();
                if (!target.ends_with(".md")) check(target, line.size());
            }
        }
        std::sort(problems.begin(), problems.end());
        problems.erase(std::unique(problems.begin(), problems.end()), problems.end());
        for (const std::string& p : problems) {
            out.push_back({rel, lineNumber, p});
        }
    });
    return out;
}

std::vector<ReferenceProblem> findUndefinedSeedWording(const fs::path& root) {
    // Prototype sense only: random-number seeds ("--seed", "seed = 3", "(seed, x, y)", "seeded")
    // stay legitimate.
    static const std::regex prototype(
        R"(\b(?:the|this)\s+(?:[\w-]+\s+){0,2}seeds?\b|\bseed's|\bseed[- ]?0\d\d)",
        std::regex::icase);
    static const std::regex identifier(R"(\bSeed[A-Z]\w*)");
    std::vector<ReferenceProblem> out;
    forEachScannedLine(root, [&](const fs::path&, const std::string& rel, int lineNumber,
                                 const std::string& text) {
        std::smatch m;
        if (std::regex_search(text, m, prototype) || std::regex_search(text, m, identifier)) {
            std::string message = m.str();
            message += " names a prototype without saying which";
            out.push_back({rel, lineNumber, message});
        }
    });
    return out;
}

}  // namespace luxel::docs
