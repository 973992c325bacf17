// Attribute-based patches against the analytic cases: boundary interpolation, the straight-edged triangle,
// the unit square, planarity, symmetry, the mean at the incentre, normals by finite differences, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "geometry/abm_patch/abm_patch.h"
#include "geometry/abm_patch/abm_patch_test_support.h"

namespace isotrace {
namespace {

using abm_test::bezier;
using abm_test::curved_loop;
using abm_test::side;

std::shared_ptr<const PatchDomain> domain_for(int n, bool dedicated) {
    if (dedicated && n == 3) return right_triangle_domain();
    if (dedicated && n == 4) return unit_square_domain();
    return regular_polygon_domain(n);
}

// The triangle (0,0,0)–(0,1,0)–(1,0,0) with straight sides, in loop order: c1 = (0, s, 0), c2 = (s, 1 − s, 0),
// c3 = (1 − s, 0, 0) (the c3(u) = (u, 0, 0) run backwards, so that c3 runs into c1).
AbmPatch straight_triangle(double p = 1) {
    return AbmPatch(right_triangle_domain(),
                    {side(bezier({{0, 0, 0}, {0, 1, 0}})), side(bezier({{0, 1, 0}, {1, 0, 0}})),
                     side(bezier({{1, 0, 0}, {0, 0, 0}}))},
                    p);
}

TEST(AbmPatch, StraightTriangleMatchesTheFormula) {
    // u = 0.2, v = 0.3: d = (0.2, 0.5/√2, 0.3), attributes c1(0.3) = (0, 0.3), c2(0.45) = (0.45, 0.55), c3(0.8) = (0.2, 0).
    const double w1 = 1 / 0.2, w2 = std::sqrt(2.0) / 0.5, w3 = 1 / 0.3, total = w1 + w2 + w3;
    const Vec3d expected{(w2 * 0.45 + w3 * 0.2) / total, (w1 * 0.3 + w2 * 0.55) / total, 0};
    const Vec3d f = straight_triangle()({0.2, 0.3});
    EXPECT_NEAR(f.x, expected.x, 1e-15);
    EXPECT_NEAR(f.y, expected.y, 1e-15);
    EXPECT_EQ(f.z, 0);
    // The figures, to their five places.
    EXPECT_NEAR(f.x, 0.17376, 5e-6);
    EXPECT_NEAR(f.y, 0.27376, 5e-6);
}

TEST(AbmPatch, PlanarUnitSquareIsTheIdentity) {
    const AbmPatch square(unit_square_domain(),
                          {side(bezier({{0, 0, 0}, {0, 1, 0}})), side(bezier({{0, 1, 0}, {1, 1, 0}})),
                           side(bezier({{1, 1, 0}, {1, 0, 0}})), side(bezier({{1, 0, 0}, {0, 0, 0}}))});
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) {
            const double u = i / 20.0, v = j / 20.0;
            const Vec3d f = square({u, v});
            EXPECT_NEAR(f.x, u, 1e-15) << u << " " << v;
            EXPECT_NEAR(f.y, v, 1e-15) << u << " " << v;
            EXPECT_EQ(f.z, 0);
        }
}

TEST(AbmPatch, InterpolatesItsBoundaryAndCorners) {
    for (int n = 3; n <= 8; ++n)
        for (bool dedicated : {true, false})
            for (double p : {1.0, 2.0, 3.5}) {
                if (dedicated && n > 4) continue;
                const AbmPatch patch(domain_for(n, dedicated), curved_loop(n), p);
                double worst = 0;
                for (int i = 0; i < n; ++i) {
                    for (int k = 0; k <= 1000; ++k) {
                        const double t = k / 1000.0;
                        worst = std::max(worst, length(patch(patch.domain().on_side(i, t)) - patch.sides()[std::size_t(i)].point(t)));
                    }
                    if (dedicated) {  // corners are domain points given exactly
                        EXPECT_EQ(patch(patch.domain().corners()[std::size_t(i)]), patch.sides()[std::size_t(i)].start());
                    }
                }
                EXPECT_LT(worst, 1e-9) << n << " sides, p = " << p << (dedicated ? ", dedicated domain" : ", polygon");
            }
}

TEST(AbmPatch, PlanarBoundaryGivesAPlanarPatch) {
    const Vec3d normal = normalize(Vec3d{0.3, -0.2, 1});
    for (int n = 3; n <= 8; ++n) {
        std::vector<PatchSide> sides = curved_loop(n);
        for (PatchSide& s : sides) {  // project every control point onto the plane through the origin
            std::vector<Vec3d> points = s.curve->control_points();
            for (Vec3d& q : points) q = q - dot(q, normal) * normal;
            s.curve = bezier(points);
        }
        const AbmPatch patch(domain_for(n, true), sides, 1.5);
        std::mt19937 random(n);
        std::uniform_real_distribution<double> unit(0, 1);
        for (int k = 0; k < 200; ++k) {
            const DomainPoint c = patch.domain().centre(), corner = patch.domain().on_side(k % n, unit(random));
            const double r = unit(random);
            const Vec3d f = patch({c.x + r * (corner.x - c.x), c.y + r * (corner.y - c.y)});
            EXPECT_NEAR(dot(f, normal), 0, 1e-14);
            EXPECT_NEAR(dot(patch.normal({c.x + 0.5 * r * (corner.x - c.x), c.y + 0.5 * r * (corner.y - c.y)}), normal), 1, 1e-12);
        }
    }
}

TEST(AbmPatch, MirrorSymmetricBoundaryGivesAMirrorSymmetricPatch) {
    // The mirror M swaps x and y; the domain's mirror swaps u and v, which exchanges sides 1 and 3 (run
    // backwards) and runs side 2 backwards. So c3(t) = M c1(1 − t) and c2(t) = M c2(1 − t).
    auto mirror = [](const Vec3d& q) { return Vec3d{q.y, q.x, q.z}; };
    const Vec3d a{0, 0, 0.4}, b{0.1, 1.2, 0}, c = mirror(b), p{-0.3, 0.5, 0.6}, q{0.5, 1.1, 0.7};
    const AbmPatch patch(right_triangle_domain(),
                         {side(bezier({a, p, b})), side(bezier({b, q, mirror(q), c})), side(bezier({c, mirror(p), a}))}, 1);
    for (double u = 0.05; u < 1; u += 0.1)
        for (double v = 0.05; u + v < 1; v += 0.1) {
            const Vec3d f = patch({u, v}), g = patch({v, u});
            EXPECT_NEAR(length(g - mirror(f)), 0, 1e-14) << u << " " << v;
        }
}

TEST(AbmPatch, IsTheMeanOfItsAttributesWhereAllDistancesAreEqual) {
    for (int n = 3; n <= 8; ++n)
        for (bool dedicated : {true, false}) {
            if (dedicated && n > 4) continue;
            const AbmPatch patch(domain_for(n, dedicated), curved_loop(n), 2);
            const DomainPoint centre = patch.domain().centre();
            Footprint footprints[PatchDomain::kMaxSides];
            patch.domain().footprints(centre, footprints);
            Vec3d mean{};
            for (int i = 0; i < n; ++i) {
                EXPECT_NEAR(footprints[i].distance, footprints[0].distance, 1e-15);
                mean = mean + patch.sides()[std::size_t(i)].point(footprints[i].parameter);
            }
            EXPECT_LT(length(patch(centre) - (1.0 / n) * mean), 1e-14) << n;
        }
}

TEST(AbmPatch, DerivativesAndNormalsMatchFiniteDifferences) {
    const double h = 1e-6;
    for (int n = 3; n <= 8; ++n)
        for (bool dedicated : {true, false})
            for (double p : {1.0, 2.5}) {
                if (dedicated && n > 4) continue;
                const AbmPatch patch(domain_for(n, dedicated), curved_loop(n), p);
                const DomainPoint c = patch.domain().centre();
                for (int k = 0; k < 3 * n; ++k) {
                    const DomainPoint edge = patch.domain().on_side(k % n, 0.1 + 0.8 * ((k * 7) % 10) / 10.0);
                    const double r = 0.15 + 0.7 * (k % 5) / 5.0;
                    const DomainPoint x{c.x + r * (edge.x - c.x), c.y + r * (edge.y - c.y)};
                    const PatchJet jet = patch.jet(x);
                    const Vec3d dx = (1 / (2 * h)) * (patch({x.x + h, x.y}) - patch({x.x - h, x.y}));
                    const Vec3d dy = (1 / (2 * h)) * (patch({x.x, x.y + h}) - patch({x.x, x.y - h}));
                    EXPECT_LT(length(jet.dx - dx), 1e-6 * (1 + length(dx))) << n << " " << p;
                    EXPECT_LT(length(jet.dy - dy), 1e-6 * (1 + length(dy))) << n << " " << p;
                    const Vec3d expected = normalize(patch.domain().orientation() * cross(dx, dy));
                    EXPECT_GT(dot(patch.normal(x), expected), 1 - 1e-9);
                }
            }
}

TEST(AbmPatch, SideAndCornerNormalsAreTheLimitsFromInside) {
    for (int n = 3; n <= 6; ++n)
        for (double p : {1.0, 2.0}) {
            const AbmPatch patch(domain_for(n, true), curved_loop(n), p);
            const DomainPoint c = patch.domain().centre();
            auto inside = [&](DomainPoint x, double step) {
                return patch.normal({x.x + step * (c.x - x.x), x.y + step * (c.y - x.y)});
            };
            for (int i = 0; i < n; ++i) {
                for (double t : {0.2, 0.5, 0.9}) {
                    const Vec3d limit = patch.side_normal(i, t);
                    EXPECT_NEAR(length(limit), 1, 1e-12);
                    EXPECT_GT(dot(limit, inside(patch.domain().on_side(i, t), 1e-5)), 0.999) << n << " p " << p << " side " << i;
                }
                // Along the line from the centre (abm_patch.h: the corner is a cone for p = 1).
                EXPECT_GT(dot(patch.corner_normal(i), inside(patch.domain().corners()[std::size_t(i)], 1e-4)), 0.999) << n << " corner " << i;
                if (p > 1) {  // then the tangent plane at the corner is the boundary curves' one
                    const Vec3d incoming = patch.sides()[std::size_t((i + n - 1) % n)].point_and_tangent(1).second;
                    const Vec3d outgoing = patch.sides()[std::size_t(i)].point_and_tangent(0).second;
                    EXPECT_GT(dot(patch.corner_normal(i), normalize(cross(incoming, outgoing))), 0.999) << n << " corner " << i;
                }
            }
        }
}

TEST(AbmPatch, FourSidedPolygonDomainIsTheSquareDomainUpToASimilarity) {
    const std::vector<PatchSide> sides = curved_loop(4);
    const AbmPatch square(unit_square_domain(), sides, 1.7), polygon(regular_polygon_domain(4), sides, 1.7);
    const auto& corner = polygon.domain().corners();  // (0,0) → corner 0, (0,1) → corner 1, (1,0) → corner 3
    for (double u = 0; u <= 1; u += 0.125)
        for (double v = 0; v <= 1; v += 0.125) {
            const DomainPoint x{corner[0].x + u * (corner[3].x - corner[0].x) + v * (corner[1].x - corner[0].x),
                                corner[0].y + u * (corner[3].y - corner[0].y) + v * (corner[1].y - corner[0].y)};
            EXPECT_LT(length(square({u, v}) - polygon(x)), 1e-12) << u << " " << v;
        }
}

TEST(AbmPatch, ThreeSidedPolygonDomainDiffersFromTheRightTriangleInside) {
    // Same boundary, different interior: the right triangle's sides have lengths 1, 1, √2 and its footprints are
    // orthogonal projections; the equilateral triangle's parameters come from the neighbours' distances.
    const std::vector<PatchSide> sides = curved_loop(3);
    const AbmPatch triangle(right_triangle_domain(), sides), polygon(regular_polygon_domain(3), sides);
    EXPECT_GT(length(triangle(triangle.domain().centre()) - polygon(polygon.domain().centre())), 1e-3);
}

// A bow-tie: the loop (0,0) → (1,1) → (1,0) → (0,1) crosses itself; its lobes cancel, so its Newell normal is zero
// and the plane its points span is used. Lifted out of the plane at alternate corners it still crosses itself
// seen from above. The straight square in the right order is accepted.
TEST(AbmPatch, RefusesALoopThatCrossesItself) {
    auto loop = [](std::vector<Vec3d> corners) {
        std::vector<PatchSide> sides;
        for (std::size_t k = 0; k < corners.size(); ++k) {
            sides.push_back(side(bezier({corners[k], corners[(k + 1) % corners.size()]})));
            sides.back().name = "curve " + std::to_string(k);
        }
        return sides;
    };
    for (const double lift : {0.0, 0.3}) {
        try {
            AbmPatch(unit_square_domain(), loop({{0, 0, 0}, {1, 1, lift}, {1, 0, 0}, {0, 1, lift}}));
            FAIL() << "a bow-tie was accepted (lift " << lift << ")";
        } catch (const std::invalid_argument& error) {
            EXPECT_NE(std::string(error.what()).find("the boundary loop crosses itself: curve 0 crosses curve 2"),
                      std::string::npos)
                << error.what();
        }
    }
    EXPECT_NO_THROW(AbmPatch(unit_square_domain(), loop({{0, 0, 0}, {0, 1, 0.3}, {1, 1, 0}, {1, 0, 0.3}})));
    for (int n = 3; n <= 8; ++n) EXPECT_NO_THROW(AbmPatch(regular_polygon_domain(n), curved_loop(n))) << n;
}

TEST(AbmPatch, RejectsBadInput) {
    const std::vector<PatchSide> loop = curved_loop(3);
    EXPECT_THROW(AbmPatch(unit_square_domain(), loop), std::invalid_argument);  // 3 curves, 4 sides
    for (double p : {0.0, -1.0, 0.5, 9.0, std::nan("")}) EXPECT_THROW(AbmPatch(right_triangle_domain(), loop, p), std::invalid_argument);
    EXPECT_THROW(regular_polygon_domain(2), std::invalid_argument);
    EXPECT_THROW(regular_polygon_domain(9), std::invalid_argument);
    EXPECT_THROW(bezier({{0, 0, 0}, {std::nan(""), 0, 0}}), std::invalid_argument);

    std::vector<PatchSide> open = loop;
    open[1].curve = bezier({open[1].start(), open[1].end() + Vec3d{0, 0, 0.25}});
    try {
        AbmPatch(right_triangle_domain(), open);
        FAIL() << "an open loop was accepted";
    } catch (const std::invalid_argument& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("not a closed loop"), std::string::npos) << message;
        EXPECT_NE(message.find("a gap of 0.25"), std::string::npos) << message;
    }
    std::vector<PatchSide> backwards = loop;
    backwards[1].reversed = true;
    try {
        AbmPatch(right_triangle_domain(), backwards);
        FAIL() << "a loop with a curve backwards was accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("reversed"), std::string::npos) << error.what();
    }
    std::vector<PatchSide> point = loop;
    const Vec3d corner = loop[0].end();
    point.insert(point.begin() + 1, side(bezier({corner, corner, corner})));
    try {
        AbmPatch(unit_square_domain(), point);
        FAIL() << "a degenerate curve was accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("degenerate"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace isotrace
