// Smooth joins: patches sharing a curve meet with one normal — in the shading normals on the curve and in the
// surface itself just inside each patch — the planar case stays planar, and p = 1 is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/abm_patch/abm_patch_test_support.h"
#include "geometry/abm_patch/smooth_joins.h"

namespace isotrace {
namespace {

using abm_test::bezier;
using abm_test::curved_tetrahedron;

double degrees_between(const Vec3d& a, const Vec3d& b) {
    return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0)) * 180 / std::numbers::pi;
}

// The domain point `inside` of the way from side i's point at λ toward the centre.
DomainPoint just_inside(const AbmPatch& patch, int side, double along, double inside) {
    const DomainPoint on = patch.domain().on_side(side, along), centre = patch.domain().centre();
    return {on.x + inside * (centre.x - on.x), on.y + inside * (centre.y - on.y)};
}

struct Jumps {
    double on_curve = 0, inside = 0;  // largest angle between the two patches' normals, degrees
};

// Along every curve of the tetrahedron (each shared by two patches running it in opposite directions, fronts
// outward): the side normals on the curve, and the surface normals 10⁻⁴ of the way inside each patch.
Jumps largest_jumps(const std::vector<AbmPatch>& patches) {
    std::map<const SpaceCurve*, std::vector<std::pair<const AbmPatch*, int>>> users;
    for (const AbmPatch& patch : patches)
        for (int i = 0; i < 3; ++i) users[patch.sides()[std::size_t(i)].curve.get()].push_back({&patch, i});
    Jumps jumps;
    for (const auto& [curve, pair] : users) {
        EXPECT_EQ(pair.size(), 2u);
        for (int k = 1; k < 20; ++k) {
            const double t = k / 20.0;
            Vec3d on[2], inside[2];
            for (int u = 0; u < 2; ++u) {
                const AbmPatch& patch = *pair[std::size_t(u)].first;
                const int side = pair[std::size_t(u)].second;
                const double along = patch.sides()[std::size_t(side)].reversed ? 1 - t : t;
                on[u] = patch.side_normal(side, along);
                inside[u] = patch.normal(just_inside(patch, side, along, 1e-4));
            }
            jumps.on_curve = std::max(jumps.on_curve, degrees_between(on[0], on[1]));
            jumps.inside = std::max(jumps.inside, degrees_between(inside[0], inside[1]));
        }
    }
    return jumps;
}

TEST(SmoothJoins, PatchesMeetWithOneNormalAlongSharedCurves) {
    for (bool polygon : {false, true}) {
        const std::vector<AbmPatch> creased = curved_tetrahedron(polygon, 2);
        const Jumps before = largest_jumps(creased);
        EXPECT_GT(before.on_curve, 30);
        EXPECT_GT(before.inside, 30);
        const Jumps after = largest_jumps(with_smooth_joins(creased));
        EXPECT_LT(after.on_curve, 0.01) << (polygon ? "polygon" : "triangle");
        EXPECT_LT(after.inside, 0.1) << (polygon ? "polygon" : "triangle");
    }
}

TEST(SmoothJoins, TheCurvesAndThePatchesCornersStay) {
    const std::vector<AbmPatch> creased = curved_tetrahedron(false, 2);
    const std::vector<AbmPatch> smooth = with_smooth_joins(creased);
    for (std::size_t p = 0; p < smooth.size(); ++p)
        for (int i = 0; i < 3; ++i)
            for (double t : {0.0, 0.3, 0.5, 1.0}) {
                const DomainPoint x = smooth[p].domain().on_side(i, t);
                EXPECT_NEAR(length(smooth[p](x) - creased[p](x)), 0, 1e-12) << p << " " << i << " " << t;
            }
}

// The unit square as two right triangles sharing the diagonal: the common normal is the plane's, each ribbon
// lies in the plane, so the smooth patches stay planar.
TEST(SmoothJoins, APlanarModelStaysPlanar) {
    const auto diagonal = bezier({{0, 0, 0}, {1, 1, 0}});
    const std::vector<AbmPatch> halves = {
        AbmPatch(right_triangle_domain(), {{diagonal, false, "d"}, {bezier({{1, 1, 0}, {0, 1, 0}}), false, "a"},
                                           {bezier({{0, 1, 0}, {0, 0, 0}}), false, "b"}}, 2),
        AbmPatch(right_triangle_domain(), {{diagonal, true, "d"}, {bezier({{0, 0, 0}, {1, 0, 0}}), false, "c"},
                                           {bezier({{1, 0, 0}, {1, 1, 0}}), false, "e"}}, 2)};
    const std::vector<AbmPatch> smooth = with_smooth_joins(halves);
    EXPECT_TRUE(smooth[0].sides()[0].ribbon && smooth[1].sides()[0].ribbon);
    EXPECT_FALSE(smooth[0].sides()[1].ribbon);  // an open edge
    for (const AbmPatch& patch : smooth)
        for (int i = 1; i < 20; ++i)
            for (int j = 1; i + j < 20; ++j) {
                const Vec3d f = patch({i / 20.0, j / 20.0});
                EXPECT_NEAR(f.z, 0, 1e-12);
                EXPECT_NEAR(std::abs(patch.normal({i / 20.0, j / 20.0}).z), 1, 1e-9);
            }
}

// The jet's ribbon terms (f_i′ ∇s_i with the ribbon's derivative, r_i ∇d_i) against central differences of F.
TEST(SmoothJoins, DerivativesMatchFiniteDifferences) {
    for (bool polygon : {false, true}) {
        const std::vector<AbmPatch> smooth = with_smooth_joins(curved_tetrahedron(polygon, 2));
        const AbmPatch& patch = smooth[0];
        for (int side = 0; side < 3; ++side)
            for (double along : {0.2, 0.5, 0.8})
                for (double inside : {0.05, 0.3, 0.7}) {
                    const DomainPoint x = just_inside(patch, side, along, inside);
                    const PatchJet jet = patch.jet(x);
                    const double h = 1e-6;
                    const Vec3d dx = (1 / (2 * h)) * (patch({x.x + h, x.y}) - patch({x.x - h, x.y}));
                    const Vec3d dy = (1 / (2 * h)) * (patch({x.x, x.y + h}) - patch({x.x, x.y - h}));
                    EXPECT_NEAR(length(jet.dx - dx), 0, 1e-5 * (1 + length(dx))) << side << " " << along << " " << inside;
                    EXPECT_NEAR(length(jet.dy - dy), 0, 1e-5 * (1 + length(dy))) << side << " " << along << " " << inside;
                }
    }
}

// A shared curve that stops at its start (a doubled control point: zero derivative there) takes the direction of
// its chord there; nothing becomes NaN.
TEST(SmoothJoins, ACurveThatStopsAtAnEndStaysFinite) {
    const auto shared = bezier({{0, 0, 0}, {0, 0, 0}, {0.5, 0.3, 0.5}, {1, 0, 1}});
    const std::vector<AbmPatch> pair = {
        AbmPatch(right_triangle_domain(), {{shared, false, "s"}, {bezier({{1, 0, 1}, {1, 0, 0}}), false, "a"},
                                           {bezier({{1, 0, 0}, {0, 0, 0}}), false, "b"}}, 2),
        AbmPatch(right_triangle_domain(), {{shared, true, "s"}, {bezier({{0, 0, 0}, {0, 0, 1}}), false, "c"},
                                           {bezier({{0, 0, 1}, {1, 0, 1}}), false, "d"}}, 2)};
    for (const AbmPatch& patch : with_smooth_joins(pair))
        for (int i = 0; i <= 20; ++i) {
            EXPECT_TRUE(is_finite(patch.side_normal(0, i / 20.0))) << i;
            for (int j = 0; i + j <= 20; ++j) EXPECT_TRUE(is_finite(patch({i / 20.0, j / 20.0}))) << i << " " << j;
        }
}

TEST(SmoothJoins, NeedAWeightExponentAboveOne) {
    EXPECT_THROW(with_smooth_joins(curved_tetrahedron(false, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace isotrace
