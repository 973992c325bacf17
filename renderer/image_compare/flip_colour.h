#pragma once
// The colour spaces of FLIP's colour pipeline (Andersson et al. 2020, section 4.1): sRGB encoding, linear RGB with
// sRGB primaries, CIE XYZ (D65), the opponent space YCxCz, CIE L*a*b* with the Hunt adjustment, and the HyAB
// distance. Constants are those of the sRGB standard (IEC 61966-2-1) and the D65 white point.
#include <array>

namespace isotrace::flip {

using Colour = std::array<double, 3>;

double srgb_decode(double encoded);  // sRGB transfer function: encoded [0, 1] -> linear
double srgb_encode(double linear);   // its inverse

Colour linear_rgb_to_xyz(const Colour& rgb);
Colour xyz_to_linear_rgb(const Colour& xyz);
// YCxCz (Johnson and Fairchild): the L*a*b* formulas without the cube root, on XYZ relative to the D65 white.
Colour xyz_to_ycxcz(const Colour& xyz);
Colour ycxcz_to_xyz(const Colour& ycxcz);
Colour xyz_to_lab(const Colour& xyz);
// Hunt adjustment: a* and b* scaled by 0.01 L*, so that dark colours differ less in chroma.
Colour hunt_adjust(const Colour& lab);
// HyAB (Abasi et al. 2020): |dL| + the Euclidean distance of (a, b).
double hyab(const Colour& a, const Colour& b);

}  // namespace isotrace::flip
