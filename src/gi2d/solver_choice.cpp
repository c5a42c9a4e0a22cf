#include "luxel/gi2d/solver_choice.h"

#include <string>

namespace luxel::gi2d {

Result<Solver2D> parseSolver2D(std::string_view text, std::string_view option) {
    for (Solver2D s : {Solver2D::Reference, Solver2D::Hrc, Solver2D::Rc}) {
        if (text == solverName(s)) return s;
    }
    std::string message(option);
    message += " '";
    message += text;
    message += "' is not one of: reference, hrc, rc";
    return Error(message);
}

const char* solverName(Solver2D solver) {
    switch (solver) {
        case Solver2D::Reference:
            return "reference";
        case Solver2D::Hrc:
            return "hrc";
        case Solver2D::Rc:
            return "rc";
    }
    return "reference";
}

Result<RcMerge> parseRcMerge(std::string_view text, std::string_view option) {
    if (text == "vanilla") return RcMerge::Vanilla;
    if (text == "bilinear-fix" || text == "fix") return RcMerge::BilinearFix;
    std::string message(option);
    message += " '";
    message += text;
    message += "' is not one of: vanilla, bilinear-fix";
    return Error(message);
}

const char* mergeName(RcMerge merge) {
    switch (merge) {
        case RcMerge::Vanilla:
            return "vanilla";
        case RcMerge::BilinearFix:
            return "bilinear-fix";
    }
    return "vanilla";
}

}  // namespace luxel::gi2d
