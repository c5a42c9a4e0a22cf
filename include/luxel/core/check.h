// Invariant checks for programmer errors. A failed check prints the expression, both operand values
// and file:line, then aborts. LUXEL_CHECK* run in every build; LUXEL_DCHECK* only in debug builds.
#pragma once

#include <sstream>
#include <string>

namespace luxel::detail {

[[noreturn]] void checkFailed(const char* file, int line, const std::string& message);

template <typename A, typename B>
[[noreturn]] void checkOpFailed(const char* file, int line, const char* expr, const A& a,
                                const B& b) {
    std::ostringstream out;
    out << "Check failed: " << expr << " with a = " << a << ", b = " << b;
    checkFailed(file, line, out.str());
}

}  // namespace luxel::detail

#define LUXEL_CHECK(cond)                                                                      \
    do {                                                                                       \
        if (!(cond)) ::luxel::detail::checkFailed(__FILE__, __LINE__, "Check failed: " #cond); \
    } while (false)

#define LUXEL_CHECK_OP(a, op, b)                                                           \
    do {                                                                                   \
        const auto& luxelA_ = (a);                                                         \
        const auto& luxelB_ = (b);                                                         \
        if (!(luxelA_ op luxelB_))                                                         \
            ::luxel::detail::checkOpFailed(__FILE__, __LINE__, #a " " #op " " #b, luxelA_, \
                                           luxelB_);                                       \
    } while (false)

#define LUXEL_CHECK_EQ(a, b) LUXEL_CHECK_OP(a, ==, b)
#define LUXEL_CHECK_NE(a, b) LUXEL_CHECK_OP(a, !=, b)
#define LUXEL_CHECK_LT(a, b) LUXEL_CHECK_OP(a, <, b)
#define LUXEL_CHECK_LE(a, b) LUXEL_CHECK_OP(a, <=, b)
#define LUXEL_CHECK_GT(a, b) LUXEL_CHECK_OP(a, >, b)
#define LUXEL_CHECK_GE(a, b) LUXEL_CHECK_OP(a, >=, b)

#ifdef NDEBUG
#define LUXEL_DCHECK(cond) \
    do {                   \
    } while (false)
#define LUXEL_DCHECK_OP(a, op, b) \
    do {                          \
    } while (false)
#else
#define LUXEL_DCHECK(cond) LUXEL_CHECK(cond)
#define LUXEL_DCHECK_OP(a, op, b) LUXEL_CHECK_OP(a, op, b)
#endif

#define LUXEL_DCHECK_EQ(a, b) LUXEL_DCHECK_OP(a, ==, b)
#define LUXEL_DCHECK_LT(a, b) LUXEL_DCHECK_OP(a, <, b)
#define LUXEL_DCHECK_LE(a, b) LUXEL_DCHECK_OP(a, <=, b)
#define LUXEL_DCHECK_GE(a, b) LUXEL_DCHECK_OP(a, >=, b)
