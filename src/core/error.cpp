#include "luxel/core/error.h"

#include <cstdio>
#include <cstdlib>

namespace luxel {

std::string SourceLocation::describe() const {
    // Appends piecewise: GCC 12 warns falsely (-Wrestrict) on `":" + std::to_string(n)`.
    std::string out = file;
    if (line > 0) {
        out.append(":").append(std::to_string(line));
        if (column > 0) out.append(":").append(std::to_string(column));
    }
    if (!field.empty()) out.append(out.empty() ? "" : ": ").append(field);
    return out;
}

Error::Error(const SourceLocation& where, const std::string& message) {
    const std::string prefix = where.describe();
    message_ = prefix.empty() ? message : prefix + ": " + message;
}

namespace detail {

void checkFailed(const char* file, int line, const std::string& message) {
    std::fprintf(stderr, "%s:%d: %s\n", file, line, message.c_str());
    std::fflush(stderr);
    std::abort();
}

}  // namespace detail
}  // namespace luxel
