#pragma once
// Small 3-vector used everywhere: float for rays and hits (Embree's precision), double for geometry that
// needs it (root finding, transforms composed from scene input).
#include <algorithm>
#include <cmath>

namespace isotrace {

template <class T>
struct Vec3T {
    T x = 0, y = 0, z = 0;

    constexpr Vec3T() = default;
    constexpr Vec3T(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
    template <class U>
    constexpr explicit Vec3T(const Vec3T<U>& v) : x(T(v.x)), y(T(v.y)), z(T(v.z)) {}

    constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3T operator-() const { return {-x, -y, -z}; }
    constexpr Vec3T& operator+=(const Vec3T& b) { x += b.x; y += b.y; z += b.z; return *this; }
    constexpr Vec3T& operator-=(const Vec3T& b) { x -= b.x; y -= b.y; z -= b.z; return *this; }
    constexpr Vec3T& operator*=(T s) { x *= s; y *= s; z *= s; return *this; }
    constexpr bool operator==(const Vec3T&) const = default;
};

template <class T> constexpr Vec3T<T> operator+(Vec3T<T> a, const Vec3T<T>& b) { return a += b; }
template <class T> constexpr Vec3T<T> operator-(Vec3T<T> a, const Vec3T<T>& b) { return a -= b; }
template <class T> constexpr Vec3T<T> operator*(Vec3T<T> a, T s) { return a *= s; }
template <class T> constexpr Vec3T<T> operator*(T s, Vec3T<T> a) { return a *= s; }
template <class T> constexpr Vec3T<T> operator/(const Vec3T<T>& a, T s) { return a * (T(1) / s); }
template <class T> constexpr Vec3T<T> operator*(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}

template <class T> constexpr T dot(const Vec3T<T>& a, const Vec3T<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T> constexpr Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T> inline T length(const Vec3T<T>& a) { return std::sqrt(dot(a, a)); }
template <class T> inline Vec3T<T> normalize(const Vec3T<T>& a) { return a / length(a); }
// a normalised, or `fallback` where a has no direction (zero, or too long or short to measure).
template <class T> inline Vec3T<T> safe_normalize(const Vec3T<T>& a, const Vec3T<T>& fallback) {
    const T len = length(a);
    return len > 0 && std::isfinite(len) ? a / len : fallback;
}
template <class T> constexpr Vec3T<T> min(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
template <class T> constexpr Vec3T<T> max(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
template <class T> constexpr T max_component(const Vec3T<T>& a) { return std::max(a.x, std::max(a.y, a.z)); }
// The axis (0–2) of the largest component; ties go to the lower axis.
template <class T> constexpr int longest_axis(const Vec3T<T>& a) { return a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2; }
template <class T> inline Vec3T<T> abs(const Vec3T<T>& a) { return {std::abs(a.x), std::abs(a.y), std::abs(a.z)}; }
template <class T> inline bool is_finite(const Vec3T<T>& a) {
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

using Vec3f = Vec3T<float>;
using Vec3d = Vec3T<double>;

// An orthonormal basis around a unit normal (Duff et al. 2017, branch-free and continuous except at n.z = -1).
template <class T>
inline void orthonormal_basis(const Vec3T<T>& n, Vec3T<T>& tangent, Vec3T<T>& bitangent) {
    const T sign = std::copysign(T(1), n.z);
    const T a = T(-1) / (sign + n.z);
    const T b = n.x * n.y * a;
    tangent = {T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x};
    bitangent = {b, sign + n.y * n.y * a, -n.y};
}

}  // namespace isotrace
