// Small constexpr vector types for CPU code (RGB colours, 2D points and directions).
#pragma once

#include <algorithm>
#include <cmath>

namespace luxel {

template <typename T>
struct Vec2T {
    T x = 0, y = 0;

    constexpr Vec2T operator+(Vec2T o) const { return {x + o.x, y + o.y}; }
    constexpr Vec2T operator-(Vec2T o) const { return {x - o.x, y - o.y}; }
    constexpr Vec2T operator*(T s) const { return {x * s, y * s}; }
    constexpr Vec2T operator/(T s) const { return {x / s, y / s}; }
    constexpr bool operator==(const Vec2T&) const = default;
};

using Vec2 = Vec2T<float>;
using Vec2d = Vec2T<double>;

template <typename T>
constexpr T dot(Vec2T<T> a, Vec2T<T> b) {
    return a.x * b.x + a.y * b.y;
}
template <typename T>
constexpr T cross(Vec2T<T> a, Vec2T<T> b) {
    return a.x * b.y - a.y * b.x;
}
template <typename T>
T length(Vec2T<T> a) {
    return std::sqrt(dot(a, a));
}

template <typename T>
struct Vec3T {
    T x = 0, y = 0, z = 0;

    constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr Vec3T operator+(Vec3T o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3T operator-(Vec3T o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3T operator*(T s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3T operator/(T s) const { return {x / s, y / s, z / s}; }
    constexpr Vec3T operator-() const { return {-x, -y, -z}; }
    constexpr bool operator==(const Vec3T&) const = default;
};

using Vec3 = Vec3T<float>;
using Vec3d = Vec3T<double>;
using Int3 = Vec3T<int>;

template <typename T>
constexpr T dot(Vec3T<T> a, Vec3T<T> b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
constexpr Vec3T<T> cross(Vec3T<T> a, Vec3T<T> b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T>
T length(Vec3T<T> a) {
    return std::sqrt(dot(a, a));
}
template <typename T>
Vec3T<T> normalize(Vec3T<T> a) {
    return a / length(a);
}

// An RGB triple: radiance, absorption coefficient or transmittance per channel.
struct Rgb {
    float r = 0, g = 0, b = 0;

    constexpr Rgb() = default;
    constexpr Rgb(float red, float green, float blue) : r(red), g(green), b(blue) {}
    constexpr explicit Rgb(float v) : r(v), g(v), b(v) {}

    constexpr float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    constexpr float& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }

    constexpr Rgb operator+(Rgb o) const { return {r + o.r, g + o.g, b + o.b}; }
    constexpr Rgb operator-(Rgb o) const { return {r - o.r, g - o.g, b - o.b}; }
    constexpr Rgb operator*(Rgb o) const { return {r * o.r, g * o.g, b * o.b}; }
    constexpr Rgb operator*(float s) const { return {r * s, g * s, b * s}; }
    constexpr Rgb& operator+=(Rgb o) { return *this = *this + o; }
    constexpr Rgb& operator*=(Rgb o) { return *this = *this * o; }
    constexpr bool operator==(const Rgb&) const = default;

    constexpr float maxComponent() const { return std::max(r, std::max(g, b)); }
    constexpr float minComponent() const { return std::min(r, std::min(g, b)); }
};

inline Rgb expRgb(Rgb v) {
    return {std::exp(v.r), std::exp(v.g), std::exp(v.b)};
}

}  // namespace luxel
