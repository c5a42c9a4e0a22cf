// The common subset of C++20 and GLSL 4.50 that luxel's shared kernel headers are written in (the
// approach of NanoVDB's PNanoVDB.h, which compiles as C, C++ and GLSL). A shared header includes
// this file and then reads the same in both languages:
//
//   LUXEL_SHARED_BEGIN                        // namespace luxel::gpu::shared { in C++
//   struct Interval { vec3 radiance; vec3 transmittance; };
//   LUXEL_FUNC Interval over(Interval near, Interval far) {
//       return Interval(near.radiance + near.transmittance * far.radiance,
//                       near.transmittance * far.transmittance);
//   }
//   LUXEL_SHARED_END
//
// Rules for shared code (GLSL has no references, templates, overloading on return type or
// swizzle-free member functions, and C++ has no swizzles):
// - functions are `LUXEL_FUNC` (inline in C++; `LUXEL_FUNC_HOT` forces inlining); out-parameters
//   are `LUXEL_INOUT(T) name`, large read-only ones `LUXEL_IN(T) name` (a const reference in C++);
// - vectors are vec2/vec3/vec4, ivec2/ivec3, uvec2/uvec3 (dvec3 in C++ only); components by
//   .x/.y/.z/.w or [i], never swizzles (.xy); construct with vec3(s) or vec3(x, y, z);
// - float literals carry the f suffix (1.0f): unsuffixed literals are double in C++;
// - structs are plain aggregates built with parentheses, Interval(a, b) (C++20 allows it);
// - no arrays as parameters (C++ passes them by pointer, GLSL by value);
// - buffer access goes through functions the includer defines, so the same kernel reads a
//   std::vector on the CPU and a storage buffer on the GPU.
#ifndef LUXEL_GPU_SHARED_GLSL_COMPAT_H
#define LUXEL_GPU_SHARED_GLSL_COMPAT_H

#ifdef __cplusplus

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#define LUXEL_SHARED_BEGIN namespace luxel::gpu::shared {
#define LUXEL_SHARED_END }
#define LUXEL_FUNC inline
// For the small functions of hot loops: always inlined in C++, so a state struct passed by
// reference stays in registers instead of memory.
#define LUXEL_FUNC_HOT inline __attribute__((always_inline))
#define LUXEL_INOUT(T) T&
#define LUXEL_IN(T) const T&
// Before a loop over the 3 axes in a hot path: unrolled, so each axis index is a constant.
#define LUXEL_UNROLL_AXES _Pragma("GCC unroll 3")
#define LUXEL_INFINITY (std::numeric_limits<float>::infinity())

namespace luxel::gpu::shared {

using uint = std::uint32_t;

// GLSL-like vectors: component-wise arithmetic with vectors and scalars on either side.
template <typename T>
struct tvec2 {
    T x = 0, y = 0;
    constexpr tvec2() = default;
    constexpr explicit tvec2(T s) : x(s), y(s) {}
    constexpr tvec2(T x_, T y_) : x(x_), y(y_) {}
    template <typename U>
    constexpr explicit tvec2(tvec2<U> v) : x(static_cast<T>(v.x)), y(static_cast<T>(v.y)) {}
    constexpr T operator[](int i) const { return i == 0 ? x : y; }
    constexpr T& operator[](int i) { return i == 0 ? x : y; }
};

template <typename T>
struct tvec3 {
    T x = 0, y = 0, z = 0;
    constexpr tvec3() = default;
    constexpr explicit tvec3(T s) : x(s), y(s), z(s) {}
    constexpr tvec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
    template <typename U>
    constexpr explicit tvec3(tvec3<U> v)
        : x(static_cast<T>(v.x)), y(static_cast<T>(v.y)), z(static_cast<T>(v.z)) {}
    constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

template <typename T>
struct tvec4 {
    T x = 0, y = 0, z = 0, w = 0;
    constexpr tvec4() = default;
    constexpr explicit tvec4(T s) : x(s), y(s), z(s), w(s) {}
    constexpr tvec4(T x_, T y_, T z_, T w_) : x(x_), y(y_), z(z_), w(w_) {}
    constexpr tvec4(tvec3<T> v, T w_) : x(v.x), y(v.y), z(v.z), w(w_) {}
    constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w)); }
    constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w)); }
};

// Component-wise operators for every vector size: op(v, v), op(v, s), op(s, v), v op= v/s.
#define LUXEL_VEC_BINARY(V, OP)                                    \
    template <typename T>                                          \
    constexpr V<T> operator OP(V<T> a, V<T> b) {                   \
        V<T> r;                                                    \
        for (int i = 0; i < kSize<V<T>>; ++i) r[i] = a[i] OP b[i]; \
        return r;                                                  \
    }                                                              \
    template <typename T>                                          \
    constexpr V<T> operator OP(V<T> a, T s) {                      \
        return a OP V<T>(s);                                       \
    }                                                              \
    template <typename T>                                          \
    constexpr V<T> operator OP(T s, V<T> a) {                      \
        return V<T>(s) OP a;                                       \
    }                                                              \
    template <typename T, typename B>                              \
    constexpr V<T>& operator OP##=(V<T>& a, B b) {                 \
        return a = a OP b;                                         \
    }

template <typename V>
inline constexpr int kSize = 0;
template <typename T>
inline constexpr int kSize<tvec2<T>> = 2;
template <typename T>
inline constexpr int kSize<tvec3<T>> = 3;
template <typename T>
inline constexpr int kSize<tvec4<T>> = 4;

#define LUXEL_VEC_OPS(V)                                                        \
    LUXEL_VEC_BINARY(V, +)                                                      \
    LUXEL_VEC_BINARY(V, -)                                                      \
    LUXEL_VEC_BINARY(V, *)                                                      \
    LUXEL_VEC_BINARY(V, /)                                                      \
    template <typename T>                                                       \
    constexpr V<T> operator-(V<T> a) {                                          \
        for (int i = 0; i < kSize<V<T>>; ++i) a[i] = -a[i];                     \
        return a;                                                               \
    }                                                                           \
    template <typename T>                                                       \
    constexpr bool operator==(V<T> a, V<T> b) {                                 \
        for (int i = 0; i < kSize<V<T>>; ++i)                                   \
            if (!(a[i] == b[i])) return false;                                  \
        return true;                                                            \
    }                                                                           \
    template <typename T>                                                       \
    constexpr T dot(V<T> a, V<T> b) {                                           \
        T s = 0;                                                                \
        for (int i = 0; i < kSize<V<T>>; ++i) s += a[i] * b[i];                 \
        return s;                                                               \
    }                                                                           \
    template <typename T>                                                       \
    constexpr V<T> min(V<T> a, V<T> b) {                                        \
        for (int i = 0; i < kSize<V<T>>; ++i) a[i] = b[i] < a[i] ? b[i] : a[i]; \
        return a;                                                               \
    }                                                                           \
    template <typename T>                                                       \
    constexpr V<T> max(V<T> a, V<T> b) {                                        \
        for (int i = 0; i < kSize<V<T>>; ++i) a[i] = a[i] < b[i] ? b[i] : a[i]; \
        return a;                                                               \
    }                                                                           \
    template <typename T>                                                       \
    V<T> exp(V<T> a) {                                                          \
        for (int i = 0; i < kSize<V<T>>; ++i) a[i] = std::exp(a[i]);            \
        return a;                                                               \
    }                                                                           \
    template <typename T>                                                       \
    V<T> abs(V<T> a) {                                                          \
        for (int i = 0; i < kSize<V<T>>; ++i) a[i] = std::abs(a[i]);            \
        return a;                                                               \
    }                                                                           \
    template <typename T>                                                       \
    V<T> floor(V<T> a) {                                                        \
        for (int i = 0; i < kSize<V<T>>; ++i) a[i] = std::floor(a[i]);          \
        return a;                                                               \
    }

LUXEL_VEC_OPS(tvec2)
LUXEL_VEC_OPS(tvec3)
LUXEL_VEC_OPS(tvec4)
#undef LUXEL_VEC_OPS
#undef LUXEL_VEC_BINARY

using vec2 = tvec2<float>;
using vec3 = tvec3<float>;
using vec4 = tvec4<float>;
using ivec2 = tvec2<int>;
using ivec3 = tvec3<int>;
using uvec2 = tvec2<uint>;
using uvec3 = tvec3<uint>;
using dvec2 = tvec2<double>;  // C++ only: the CPU reference passes may run in double
using dvec3 = tvec3<double>;

// GLSL built-ins on scalars (the std:: ones, plus those std lacks under the GLSL name).
using std::abs;
using std::acos;
using std::ceil;
using std::cos;
using std::exp;
using std::floor;
using std::log;
using std::pow;
using std::sin;
using std::sqrt;
// GLSL's two-argument atan (atan2).
inline float atan(float y, float x) {
    return std::atan2(y, x);
}
// Index of the highest set bit, -1 for 0 (GLSL findMSB; callers pass non-negative values).
constexpr int findMSB(int v) {
    return v <= 0 ? -1 : 31 - std::countl_zero(static_cast<unsigned>(v));
}
template <typename T>
constexpr T min(T a, T b) {
    return b < a ? b : a;
}
template <typename T>
constexpr T max(T a, T b) {
    return a < b ? b : a;
}
template <typename T>
constexpr T clamp(T v, T lo, T hi) {
    return min(max(v, lo), hi);
}
template <typename T>
constexpr T mix(T a, T b, float t) {
    return a + (b - a) * t;
}
template <typename T>
T length(tvec3<T> v) {
    return std::sqrt(dot(v, v));
}
template <typename T>
tvec3<T> normalize(tvec3<T> v) {
    return v * (T(1) / length(v));
}
template <typename T>
constexpr tvec3<T> cross(tvec3<T> a, tvec3<T> b) {
    return tvec3<T>(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

}  // namespace luxel::gpu::shared

#else  // GLSL

#define LUXEL_SHARED_BEGIN
#define LUXEL_SHARED_END
#define LUXEL_FUNC
#define LUXEL_FUNC_HOT
#define LUXEL_INOUT(T) inout T
#define LUXEL_IN(T) in T
#define LUXEL_UNROLL_AXES
#define LUXEL_INFINITY (uintBitsToFloat(0x7f800000u))
// The index of an invocation of a one-dimensional dispatch (gpu::Dispatch::setLinearThreads),
// whose workgroups the runtime folds into rows of at most 65535.
#define LUXEL_LINEAR_INVOCATION \
    (gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x))

#endif

#endif
