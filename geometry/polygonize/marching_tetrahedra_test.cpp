#include "geometry/polygonize/marching_tetrahedra.h"

#include <gtest/gtest.h>

#include "renderer/math/vec3.h"

namespace isotrace {
namespace {

Vec3d corner(int c) { return {double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1)}; }

TEST(PolygonizerTetrahedra, KuhnSplitFillsTheCube) {
    double volume = 0;
    for (const auto& t : kuhn_tetrahedra()) {
        EXPECT_EQ(t[0], 0);
        EXPECT_EQ(t[3], 7);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(t[std::size_t(k)] & t[std::size_t(k + 1)], t[std::size_t(k)]);
        volume += std::abs(dot(corner(t[1]), cross(corner(t[2]), corner(t[3])))) / 6;
    }
    EXPECT_DOUBLE_EQ(volume, 1.0);
}

// For every inside/outside pattern: the right number of triangles, each on inside→outside edges, facing outwards
// (its normal, taken at the edge midpoints, points from the inside corners to the outside ones).
TEST(PolygonizerTetrahedra, TrianglesCrossFromInsideToOutsideAndFaceOut) {
    std::array<CutTriangle, 2> cut;
    for (const auto& tetrahedron : kuhn_tetrahedra()) {
        for (int mask = 0; mask < 256; ++mask) {
            int inside = 0;
            for (int c : tetrahedron) inside += (mask >> c) & 1;
            const int count = cut_tetrahedron(tetrahedron, std::uint8_t(mask), cut);
            EXPECT_EQ(count, inside == 2 ? 2 : (inside == 1 || inside == 3) ? 1 : 0) << mask;
            Vec3d inside_centre, outside_centre;
            for (int c : tetrahedron) ((mask >> c) & 1 ? inside_centre : outside_centre) += corner(c);
            inside_centre = inside_centre / double(inside == 0 ? 1 : inside);
            outside_centre = outside_centre / double(inside == 4 ? 1 : 4 - inside);
            for (int t = 0; t < count; ++t) {
                Vec3d p[3];
                for (int k = 0; k < 3; ++k) {
                    const CutEdge& e = cut[std::size_t(t)][std::size_t(k)];
                    EXPECT_TRUE((mask >> e.inside_corner) & 1);
                    EXPECT_FALSE((mask >> e.outside_corner) & 1);
                    p[k] = 0.5 * (corner(e.inside_corner) + corner(e.outside_corner));
                }
                EXPECT_GT(dot(cross(p[1] - p[0], p[2] - p[0]), outside_centre - inside_centre), 0) << mask;
            }
        }
    }
}

}  // namespace
}  // namespace isotrace
