#include "renderer/image_compare/flip_colour.h"

#include <cmath>

namespace isotrace::flip {
namespace {

// D65 white in XYZ (Y = 1), and its reciprocal, as FLIP normalises.
constexpr Colour kWhite = {0.950428545, 1.0, 1.088900371};

Colour times(const double (&m)[3][3], const Colour& c) {
    return {m[0][0] * c[0] + m[0][1] * c[1] + m[0][2] * c[2], m[1][0] * c[0] + m[1][1] * c[1] + m[1][2] * c[2],
            m[2][0] * c[0] + m[2][1] * c[1] + m[2][2] * c[2]};
}

}  // namespace

double srgb_decode(double encoded) {
    return encoded > 0.04045 ? std::pow((encoded + 0.055) / 1.055, 2.4) : encoded / 12.92;
}

double srgb_encode(double linear) {
    return linear > 0.0031308 ? 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055 : 12.92 * linear;
}

Colour linear_rgb_to_xyz(const Colour& rgb) {
    // The sRGB primaries and D65 white, as exact fractions.
    static constexpr double m[3][3] = {
        {10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
        {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
        {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0}};
    return times(m, rgb);
}

Colour xyz_to_linear_rgb(const Colour& xyz) {
    static constexpr double m[3][3] = {{3.241003275, -1.537398934, -0.498615861},
                                       {-0.969224334, 1.875930071, 0.041554224},
                                       {0.055639423, -0.204011202, 1.057148933}};
    return times(m, xyz);
}

Colour xyz_to_ycxcz(const Colour& xyz) {
    const double x = xyz[0] / kWhite[0], y = xyz[1] / kWhite[1], z = xyz[2] / kWhite[2];
    return {116 * y - 16, 500 * (x - y), 200 * (y - z)};
}

Colour ycxcz_to_xyz(const Colour& ycxcz) {
    const double y = (ycxcz[0] + 16) / 116;
    return {(y + ycxcz[1] / 500) * kWhite[0], y * kWhite[1], (y - ycxcz[2] / 200) * kWhite[2]};
}

Colour xyz_to_lab(const Colour& xyz) {
    constexpr double delta = 6.0 / 29.0;
    const auto f = [&](double t) { return t > delta * delta * delta ? std::cbrt(t) : t / (3 * delta * delta) + 4.0 / 29.0; };
    const double fx = f(xyz[0] / kWhite[0]), fy = f(xyz[1] / kWhite[1]), fz = f(xyz[2] / kWhite[2]);
    return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

Colour hunt_adjust(const Colour& lab) { return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]}; }

double hyab(const Colour& a, const Colour& b) {
    return std::abs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]);
}

}  // namespace isotrace::flip
