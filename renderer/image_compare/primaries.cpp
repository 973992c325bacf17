#include "renderer/image_compare/primaries.h"

#include <cmath>
#include <stdexcept>

namespace isotrace {
namespace {

Transform linear_map(const std::array<std::array<double, 3>, 3>& rows) {
    Transform::Matrix m{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m[std::size_t(r)][std::size_t(c)] = rows[std::size_t(r)][std::size_t(c)];
    m[3][3] = 1;
    return Transform::from_matrix(m);
}

// XYZ of the chromaticity (x, y) at Y = 1.
Vec3d xyz_of(double x, double y) {
    if (!(y > 0) || !std::isfinite(x)) throw std::invalid_argument("chromaticities: y must be > 0");
    return {x / y, 1.0, (1 - x - y) / y};
}

// RGB -> XYZ: the primaries' XYZ as columns, each scaled so that RGB (1, 1, 1) is the white at Y = 1.
Transform rgb_to_xyz(const Chromaticities& c) {
    const Vec3d r = xyz_of(c[0], c[1]), g = xyz_of(c[2], c[3]), b = xyz_of(c[4], c[5]);
    const Transform primaries = linear_map({{{r.x, g.x, b.x}, {r.y, g.y, b.y}, {r.z, g.z, b.z}}});
    const Vec3d scale = primaries.inverse().vector(xyz_of(c[6], c[7]));
    return primaries * Transform::scale(scale);
}

// Bradford's cone response matrix (Lam 1985).
const Transform& bradford() {
    static const Transform m =
        linear_map({{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}});
    return m;
}

}  // namespace

Transform to_linear_srgb(const Chromaticities& chromaticities) {
    const Vec3d source_white = bradford().vector(xyz_of(chromaticities[6], chromaticities[7]));
    const Vec3d d65 = bradford().vector(xyz_of(kSrgbChromaticities[6], kSrgbChromaticities[7]));
    const Transform adapt = bradford().inverse() *
                            Transform::scale({d65.x / source_white.x, d65.y / source_white.y, d65.z / source_white.z}) *
                            bradford();
    return rgb_to_xyz(kSrgbChromaticities).inverse() * adapt * rgb_to_xyz(chromaticities);
}

void convert_colours(RgbImage& image, const Transform& map) {
    for (std::size_t i = 0; i < image.pixel_count(); ++i) {
        float* p = image.values.data() + 3 * i;
        const Vec3d v = map.vector(Vec3d(p[0], p[1], p[2]));
        p[0] = float(v.x);
        p[1] = float(v.y);
        p[2] = float(v.z);
    }
}

}  // namespace isotrace
