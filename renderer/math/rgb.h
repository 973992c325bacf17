#pragma once
// Linear RGB triple. Always in the render's working colour space unless a name says otherwise.
#include <cmath>

namespace isotrace {

struct Rgb {
    float r = 0, g = 0, b = 0;

    constexpr Rgb() = default;
    constexpr Rgb(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit Rgb(float v) : r(v), g(v), b(v) {}

    constexpr Rgb& operator+=(const Rgb& o) { r += o.r; g += o.g; b += o.b; return *this; }
    constexpr Rgb& operator*=(const Rgb& o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
    constexpr Rgb& operator*=(float s) { r *= s; g *= s; b *= s; return *this; }
    constexpr bool operator==(const Rgb&) const = default;

    constexpr float max() const { return r > g ? (r > b ? r : b) : (g > b ? g : b); }
    constexpr bool is_black() const { return r == 0 && g == 0 && b == 0; }
    bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
};

constexpr Rgb operator+(Rgb a, const Rgb& b) { return a += b; }
constexpr Rgb operator*(Rgb a, const Rgb& b) { return a *= b; }
constexpr Rgb operator*(Rgb a, float s) { return a *= s; }
constexpr Rgb operator*(float s, Rgb a) { return a *= s; }

}  // namespace isotrace
