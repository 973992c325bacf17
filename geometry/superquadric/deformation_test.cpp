// Barr's deformations one by one and chained: inverses undo the forward maps, Jacobians match finite differences,
// boxes map conservatively both ways, invalid parameters are refused, and the twist keeps the z axis.
#include "geometry/superquadric/deformation_chain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "geometry/superquadric/superquadric_test_support.h"

namespace isotrace {
namespace {

using superquadric_test::random_deformations;

const Vec3d kRadii(0.8, 0.5, 1.5);

// A random point of the solid superellipsoid (by rejection from its box).
Vec3d random_point_of(std::mt19937& random, const Superellipsoid& shape) {
    std::uniform_real_distribution<double> unit(-1, 1);
    for (;;) {
        const Vec3d p{shape.radii().x * unit(random), shape.radii().y * unit(random), shape.radii().z * unit(random)};
        if (shape.gauge(p) <= 1) return p;
    }
}

Vec3d random_point_in(std::mt19937& random, const IntervalBox& box) {
    std::uniform_real_distribution<double> unit(0, 1);
    return {box.x.lo + box.x.width() * unit(random), box.y.lo + box.y.width() * unit(random),
            box.z.lo + box.z.width() * unit(random)};
}

// Every single stage kind, at strengths that are valid over the radii box, including a bend region shorter than
// the object (tangent continuation beyond it) and a negative-direction bend.
std::vector<Deformation> single_stages() {
    return {Taper(0.7, -0.5, kRadii.z), Twist(1.2, kRadii.z), Bend(0.4, 0.3, 0.2, {-1.5, 1.5}),
            Bend(0.6, 2.5, -0.2, {-0.5, 0.8}), Taper(-0.9, 2, kRadii.z)};
}

TEST(SuperquadricDeformation, InversesUndoTheForwardMaps) {
    std::mt19937 random(11);
    const Superellipsoid shape{kRadii, 1, 1};
    for (const Deformation& stage : single_stages()) {
        DeformationChain chain(shape);
        chain.append(stage);
        for (int i = 0; i < 500; ++i) {
            const Vec3d p = random_point_of(random, shape);
            const Vec3d q = chain.forward(p);
            ASSERT_TRUE(chain.deformed_box().contains(q));
            const auto back = chain.inverse(q);
            ASSERT_TRUE(back);
            EXPECT_NEAR(length(*back - p), 0, 1e-12) << "stage " << stage.index();
        }
    }
    for (int c = 0; c < 20; ++c) {
        DeformationChain chain(shape);
        for (const Deformation& stage : random_deformations(random, kRadii)) chain.append(stage);
        for (int i = 0; i < 200; ++i) {
            const Vec3d p = random_point_of(random, shape);
            const auto back = chain.inverse(chain.forward(p));
            ASSERT_TRUE(back);
            EXPECT_NEAR(length(*back - p), 0, 1e-11);
        }
    }
}

TEST(SuperquadricDeformation, JacobiansMatchFiniteDifferences) {
    std::mt19937 random(12);
    const IntervalBox box = Superellipsoid{kRadii, 1, 1}.bounding_box();
    for (const Deformation& stage : single_stages()) {
        for (int i = 0; i < 200; ++i) {
            const Vec3d p = random_point_in(random, box);
            const Jacobian j = std::visit([&](const auto& s) { return s.jacobian(p); }, stage);
            for (int k = 0; k < 3; ++k) {
                Vec3d a = p, b = p;
                const double h = 1e-6;
                a[k] -= h;
                b[k] += h;
                const auto f = [&](const Vec3d& x) { return std::visit([&](const auto& s) { return s.forward(x); }, stage); };
                const Vec3d expected = (f(b) - f(a)) / (2 * h);
                // The bend's region ends are kinks of the z derivative: skip points next to them.
                if (stage.index() == 2 && k == 2 && std::abs(std::abs(p.z) - 1.5) < 2 * h) continue;
                if (stage.index() == 2 && k == 2 && (std::abs(p.z + 0.5) < 2 * h || std::abs(p.z - 0.8) < 2 * h)) continue;
                EXPECT_NEAR(length(j.column[k] - expected), 0, 1e-6) << "stage " << stage.index() << " column " << k;
            }
        }
    }
}

// The twist's inverse and Jacobian from one sine and cosine are its separate ones bit for bit (they rely on sincos
// being odd in the sine and even in the cosine), at rates of both signs turning by up to many whole turns.
TEST(SuperquadricDeformation, TheTwistsInverseAndJacobianTogetherAreTheSeparateOnes) {
    std::mt19937 random(15);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (const double rate : {1.2, -0.7, 40.0, -1e-9, 3e4}) {
        const Twist twist(rate, kRadii.z);
        for (int i = 0; i < 2000; ++i) {
            const Vec3d q{kRadii.x * unit(random), kRadii.y * unit(random), kRadii.z * unit(random)};
            const auto [preimage, jacobian] = twist.inverse_and_jacobian(q);
            const Vec3d expected = twist.inverse(q);
            const Jacobian separate = twist.jacobian(expected);
            ASSERT_EQ(preimage, expected) << rate;
            for (int k = 0; k < 3; ++k) ASSERT_EQ(jacobian.column[k], separate.column[k]) << rate << " column " << k;
        }
    }
}

// A curve's velocity carried back through random chains is the derivative of the inverse along it (Newton steps of
// the ray search in the undeformed frame), and the point is the inverse's.
TEST(SuperquadricDeformation, InverseAlongCarriesVelocitiesBack) {
    std::mt19937 random(14);
    std::uniform_real_distribution<double> unit(-1, 1);
    const Superellipsoid shape{kRadii, 0.7, 1.3};
    for (int c = 0; c < 20; ++c) {
        DeformationChain chain(shape);
        for (const Deformation& stage : random_deformations(random, kRadii)) chain.append(stage);
        for (int i = 0; i < 50; ++i) {
            const Vec3d q = chain.forward(random_point_of(random, shape)), d{unit(random), unit(random), unit(random)};
            Vec3d velocity = d;
            const auto undeformed = chain.inverse_along(q, velocity);
            ASSERT_TRUE(undeformed);
            constexpr auto kGauge = DeformationChain::BeyondUndeformedBox::Gauge;
            EXPECT_EQ(*undeformed, *chain.inverse(q, kGauge));
            const double h = 1e-6;
            const auto ahead = chain.inverse(q + d * h, kGauge), behind = chain.inverse(q - d * h, kGauge);
            if (!ahead || !behind) continue;
            EXPECT_NEAR(length(velocity - (*ahead - *behind) / (2 * h)), 0, 1e-5 * (1 + length(velocity))) << c << " " << i;
        }
    }
}

TEST(SuperquadricDeformation, BoxesMapConservativelyBothWays) {
    std::mt19937 random(13);
    std::uniform_real_distribution<double> unit(0, 1);
    const IntervalBox box = Superellipsoid{kRadii, 1, 1}.bounding_box();
    for (const Deformation& stage : single_stages()) {
        const auto forward = [&](const Vec3d& x) { return std::visit([&](const auto& s) { return s.forward(x); }, stage); };
        const auto inverse = [&](const Vec3d& x) { return std::visit([&](const auto& s) { return s.inverse(x); }, stage); };
        for (int i = 0; i < 300; ++i) {
            // A random sub-box of the object's box and points in it.
            IntervalBox sub = IntervalBox::point(random_point_in(random, box));
            sub.extend(random_point_in(random, box));
            const IntervalBox image = std::visit([&](const auto& s) { return s.forward_box(sub); }, stage);
            IntervalBox deformed_sub = IntervalBox::point(forward(sub.lower()));
            for (int k = 0; k < 50; ++k) {
                const Vec3d p = random_point_in(random, sub);
                const Vec3d q = forward(p);
                deformed_sub.extend(q);
                for (int a = 0; a < 3; ++a) {
                    EXPECT_GE(q[a], image[a].lo - 1e-12);
                    EXPECT_LE(q[a], image[a].hi + 1e-12);
                }
            }
            // Inverse: a box around deformed points bounds their preimages.
            const IntervalBox preimage = std::visit([&](const auto& s) { return s.inverse_box(deformed_sub); }, stage);
            for (int k = 0; k < 50; ++k) {
                const Vec3d q = random_point_in(random, deformed_sub);
                const Vec3d p = inverse(q);
                for (int a = 0; a < 3; ++a) {
                    EXPECT_GE(p[a], preimage[a].lo - 1e-12) << "stage " << stage.index();
                    EXPECT_LE(p[a], preimage[a].hi + 1e-12) << "stage " << stage.index();
                }
            }
        }
    }
}

// The bend's inverse box takes the angles about the bend's centre from the box's two extreme corners: boxes anywhere
// around the centre (on it, beside it, across the direction opposite the region's middle, thin and wide) bound the
// inverses of their points.
TEST(SuperquadricDeformation, TheBendsInverseBoxHoldsItsPointsAllAroundTheCentre) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> unit(0, 1), signed_unit(-1, 1);
    for (int i = 0; i < 2000; ++i) {
        const double curvature = 0.3 + 1.5 * unit(random), centre = signed_unit(random);
        const double low = centre - 2 * unit(random), high = low + std::min(0.1 + 2 * unit(random), 3.1 / curvature);
        const Bend bend(curvature, 6.3 * unit(random), centre, {low, high});
        // A box within three radii of the bend's centre, which lies at distance 1/k along the bend direction.
        const double reach = 3 / curvature;
        const Vec3d corner{reach * signed_unit(random), reach * signed_unit(random), centre + reach * signed_unit(random)};
        const Vec3d size = Vec3d(unit(random), unit(random), unit(random)) * (i % 3 == 0 ? 0.01 : reach);
        const IntervalBox box{{corner.x, corner.x + size.x}, {corner.y, corner.y + size.y}, {corner.z, corner.z + size.z}};
        const IntervalBox preimage = bend.inverse_box(box);
        for (int k = 0; k < 40; ++k) {
            const Vec3d p = bend.inverse(random_point_in(random, box));
            for (int a = 0; a < 3; ++a) {
                EXPECT_GE(p[a], preimage[a].lo - 1e-12) << i;
                EXPECT_LE(p[a], preimage[a].hi + 1e-12) << i;
            }
        }
    }
}

// A box that turns about the bend's centre within the region has for its inverse box the bounding box of its points'
// preimages, not more: its nearest and farthest points from the centre and its extreme angles about it bound them
// (interval rotations by the box's range of angles took up to twice that width).
TEST(SuperquadricDeformation, TheBendsInverseBoxIsTightWithinTheRegion) {
    std::mt19937 random(29);
    std::uniform_real_distribution<double> unit(0, 1), signed_unit(-1, 1);
    int tested = 0;
    for (int i = 0; i < 500; ++i) {
        // Bent along x or along y, so that a box of the bend's frame (s along the bend direction, z) is one of space.
        const double curvature = 0.3 + 1.2 * unit(random);
        const bool along_x = i % 2 == 0;
        const Bend bend(curvature, along_x ? 0 : std::numbers::pi / 2, 0, {-1, 1});
        const auto point = [&](double s, double z) { return along_x ? Vec3d(s, 0.1, z) : Vec3d(-0.1, s, z); };
        const auto s_of = [&](const Vec3d& p) { return along_x ? p.x : p.y; };
        const double s = (0.9 / curvature) * signed_unit(random), z = signed_unit(random);
        const double size = (i % 4 < 2 ? 0.02 : 0.3) * unit(random) + 1e-3;
        IntervalBox box = IntervalBox::point(point(s, z));
        box.extend(point(s + size, z + size));
        const IntervalBox preimage = bend.inverse_box(box);
        // The preimages of the box's edges, densely: the extremes lie on them.
        Interval seen_s{1e300, -1e300}, seen_z{1e300, -1e300};
        bool in_region = true;
        for (int k = 0; k <= 400; ++k) {
            const double f = k / 400.0;
            for (const Vec3d q : {point(s + f * size, z), point(s + f * size, z + size), point(s, z + f * size),
                                  point(s + size, z + f * size)}) {
                const Vec3d p = bend.inverse(q);
                in_region = in_region && p.z > -1 && p.z < 1;
                seen_s = hull(seen_s, Interval::point(s_of(p)));
                seen_z = hull(seen_z, Interval::point(p.z));
            }
        }
        if (!in_region) continue;
        ++tested;
        const Interval preimage_s = along_x ? preimage.x : preimage.y;
        EXPECT_LE(preimage.z.width(), seen_z.width() * 1.001 + 1e-9) << i;
        EXPECT_LE(preimage_s.width(), seen_s.width() * 1.001 + 1e-9) << i;
    }
    EXPECT_GT(tested, 200);
    // A slight bend's preimage of a box is the box itself, to the last digits: nothing of size 1/k is formed.
    const IntervalBox box{{-0.8, 0.8}, {-0.5, 0.5}, {-0.9, 0.9}};
    const IntervalBox preimage = Bend(1e-12, 0, 0, {-1, 1}).inverse_box(box);
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(preimage[a].lo, box[a].lo, 1e-11) << a;
        EXPECT_NEAR(preimage[a].hi, box[a].hi, 1e-11) << a;
    }
}

// Regression: sin_range took the cosine of θ − π/2, which rounds to the ulp of π/2 and so keeps only ~10⁻⁴ of a
// 10⁻¹² sine's relative precision; the bend's forward box divides that sine by the curvature, and an identity bend
// (k = 10⁻¹²) cut 5·10⁻⁵ off its object's bottom face (the stage box then said "outside" there, and rays missed a
// sliver of the object).
TEST(SuperquadricDeformation, ASlightBendsBoxHoldsItsObject) {
    const Interval tiny = sin_range({-1.1e-12, 1.1e-12});
    EXPECT_LE(tiny.lo, std::sin(-1.1e-12));
    EXPECT_GE(tiny.hi, std::sin(1.1e-12));
    const Bend bend(1e-12, 0.4, 0, {-1.1, 1.1});
    const IntervalBox box{{-0.8, 0.8}, {-0.5, 0.5}, {-1.1, 1.1}};
    const IntervalBox image = bend.forward_box(box);
    for (const double x : {box.x.lo, box.x.hi})
        for (const double y : {box.y.lo, box.y.hi})
            for (const double z : {box.z.lo, box.z.hi}) {
                const Vec3d q = bend.forward({x, y, z});
                for (int a = 0; a < 3; ++a) {
                    EXPECT_GE(q[a], image[a].lo - 1e-12) << x << " " << y << " " << z;
                    EXPECT_LE(q[a], image[a].hi + 1e-12) << x << " " << y << " " << z;
                }
            }
}

std::string problem_of(const Deformation& stage) {
    DeformationChain chain(Superellipsoid{kRadii, 1, 1});
    try {
        chain.append(stage);
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return {};
}

TEST(SuperquadricDeformation, SingularInversesAreRefused) {
    EXPECT_EQ(problem_of(Taper(-0.98, 0, kRadii.z)), "");
    EXPECT_NE(problem_of(Taper(-1, 0, kRadii.z)).find("taper"), std::string::npos);
    EXPECT_NE(problem_of(Taper(0, -1.5, kRadii.z)).find("cross-section scale"), std::string::npos);
    // k times the lateral extent (0.8 toward +x) must stay below 1.
    EXPECT_EQ(problem_of(Bend(1.2, 0, 0, {-0.1, 0.1})), "");
    EXPECT_NE(problem_of(Bend(1.3, 0, 0, {-0.1, 0.1})).find("fold through"), std::string::npos);
    // Toward +y the extent is 0.5.
    EXPECT_EQ(problem_of(Bend(1.9, 1.5707963267948966, 0, {-0.1, 0.1})), "");
    // More than 180 degrees over the region.
    EXPECT_NE(problem_of(Bend(1.1, 0, 0, {-1.5, 1.5})).find("180"), std::string::npos);
    DeformationChain chain(Superellipsoid{kRadii, 1, 1});
    for (int i = 0; i < DeformationChain::kMaxStages; ++i) chain.append(Twist(0.1, kRadii.z));
    EXPECT_THROW(chain.append(Twist(0.1, kRadii.z)), std::invalid_argument);
}

// Chains of twists and at most one taper keep a cone about z around the object: every deformed point of the solid
// lies inside it. A bend or a second taper leaves none.
TEST(SuperquadricDeformation, TheEnclosingConeHoldsTheDeformedSolid) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> unit(-1, 1), exponent(0.1, 3);
    const auto inside = [](const ConeAboutZ& cone, const Vec3d& p) {
        const double x = cone.kx * p.x, y = cone.ky * p.y, w = cone.radius_scale(p.z);
        return x * x + y * y <= w * w;
    };
    int points = 0;
    for (int i = 0; i < 200; ++i) {
        const Superellipsoid shape{kRadii, exponent(random), exponent(random)};
        DeformationChain chain(shape);
        const Deformation twist = Twist(2 * unit(random), kRadii.z), taper = Taper(0.8 * unit(random), 0.8 * unit(random), kRadii.z);
        switch (i % 4) {
            case 0: chain.append(twist); break;
            case 1: chain.append(taper); break;
            case 2: chain.append(twist), chain.append(taper); break;
            default: chain.append(taper), chain.append(twist), chain.append(twist); break;
        }
        ASSERT_TRUE(chain.enclosing_cone()) << i;
        for (int k = 0; k < 200; ++k, ++points) {
            const Vec3d q = chain.forward(random_point_of(random, shape));
            EXPECT_TRUE(inside(*chain.enclosing_cone(), q)) << i << " " << k;
        }
    }
    EXPECT_EQ(points, 40000);
    DeformationChain bent(Superellipsoid{kRadii, 1, 1});
    bent.append(Bend(0.4, 0.3, 0.2, {-1.5, 1.5}));
    EXPECT_FALSE(bent.enclosing_cone());
    DeformationChain tapered_twice(Superellipsoid{kRadii, 1, 1});
    tapered_twice.append(Taper(0.3, 0.3, kRadii.z));
    tapered_twice.append(Taper(0.2, -0.2, kRadii.z));
    EXPECT_FALSE(tapered_twice.enclosing_cone());
}

TEST(SuperquadricDeformation, TwistKeepsTheAxisAndTaperKeepsTheBottom) {
    const Twist twist(2.0, kRadii.z);
    for (double z : {-1.5, -0.3, 0.0, 1.5}) EXPECT_EQ(twist.forward({0, 0, z}), Vec3d(0, 0, z));
    // The top turns by rate · 2 · a3.
    const Vec3d top = twist.forward({1, 0, kRadii.z});
    EXPECT_NEAR(std::atan2(top.y, top.x), std::remainder(2.0 * 2 * kRadii.z, 2 * 3.141592653589793), 1e-12);
    const Taper taper(0.5, -0.25, kRadii.z);
    EXPECT_EQ(taper.forward({0.3, 0.2, -kRadii.z}), Vec3d(0.3, 0.2, -kRadii.z));
    const Vec3d scaled = taper.forward({0.4, 0.4, kRadii.z});
    EXPECT_NEAR(scaled.x, 0.4 * 1.5, 1e-15);
    EXPECT_NEAR(scaled.y, 0.4 * 0.75, 1e-15);
}

TEST(SuperquadricDeformation, BendWrapsTheAxisOntoACircle) {
    // Curvature 0.5 toward +x about z0 = 0: the axis point at height z goes to the circle of radius 2 about (2, 0).
    const Bend bend(0.5, 0, 0, {-1.5, 1.5});
    for (double z : {-1.5, -0.7, 0.0, 0.4, 1.5}) {
        const Vec3d q = bend.forward({0, 0, z});
        EXPECT_NEAR(std::hypot(q.x - 2, q.z), 2.0, 1e-12);
        EXPECT_NEAR(std::atan2(q.z, 2 - q.x), 0.5 * z, 1e-12);  // arc length is preserved on the axis
        EXPECT_EQ(q.y, 0);
    }
    // Beyond the region the object continues along the tangent.
    const Bend short_region(0.5, 0, 0, {-0.5, 0.5});
    const Vec3d end = short_region.forward({0, 0, 0.5}), beyond = short_region.forward({0, 0, 1.5});
    EXPECT_NEAR(length(beyond - end), 1.0, 1e-12);
    EXPECT_NEAR(dot(normalize(beyond - end), Vec3d(std::sin(0.25), 0, std::cos(0.25))), 1.0, 1e-12);
}

// The bend's centre axis (a = k·s − 1 = 0 and z at the centre) has no angle: the inverse takes its cosine and sine
// from the angle then, not from the zero vector (which gives NaN), so a field asked there stays finite.
TEST(SuperquadricDeformation, TheBendsInverseIsFiniteOnItsCentreAxis) {
    const Bend bend(0.5, 0, 0, {-1.5, 1.5});
    for (double w : {-0.3, 0.0, 0.8}) {
        const Vec3d back = bend.inverse({2, w, 0});
        EXPECT_TRUE(std::isfinite(back.x) && std::isfinite(back.y) && std::isfinite(back.z)) << w;
        EXPECT_EQ(back.y, w);
    }
}

// The levels a lone taper keeps convex: the cross-section's half-width a·f(z)·s·r(z/(s·a3)) is concave in z there (second
// differences on a fine grid), for exponents from boxy to the cone (p1 = 1, where no nonzero rate keeps any level),
// and beyond them, at twice the level, a rate of -0.9 on an ellipsoid's profile is not.
TEST(SuperquadricDeformation, ATapersConvexLevelsKeepTheCrossSectionsConcave) {
    constexpr double kA3 = 0.7;
    const auto half_width_is_concave = [&](double rate, double p1, double s) {
        const Taper taper(rate, rate, kA3);
        const auto width = [&](double z) {
            const double u = std::min(1.0, std::abs(z) / (s * kA3));
            const double scale = taper.forward({1, 1, z}).x;  // f(z): the taper of x = 1
            return scale * s * std::pow(1 - std::pow(u, p1), 1 / p1);
        };
        constexpr int kSteps = 20000;
        const double h = 2 * s * kA3 / kSteps;
        for (int i = 1; i < kSteps; ++i) {
            const double z = -s * kA3 + i * h;
            if (width(z - h) - 2 * width(z) + width(z + h) > 1e-12) return false;
        }
        return true;
    };
    for (const double p1 : {1.0, 1.01, 1.5, 2.0, 4.0, 20.0, 100.0})
        for (const double rate : {-0.95, -0.6, -0.2, 0.0, 0.3, 1.0, 3.0}) {
            const double levels = Taper(rate, rate, kA3).convex_levels(p1);
            if (rate == 0) {
                EXPECT_TRUE(std::isinf(levels));
                continue;
            }
            if (p1 == 1.0) {
                EXPECT_EQ(levels, 0.0);
                continue;
            }
            EXPECT_GT(levels, 0.0);
            for (const double s : {std::min(levels, 1.0), levels}) {
                if (!std::isfinite(s)) continue;
                EXPECT_TRUE(half_width_is_concave(rate, p1, s)) << "p1 " << p1 << ", rate " << rate << ", level " << s;
            }
        }
    EXPECT_FALSE(half_width_is_concave(-0.9, 2.0, 2 * Taper(-0.9, -0.9, kA3).convex_levels(2.0)));
    // The benchmark scene's taper keeps the levels a leaving ray starts at, on an ellipsoid and on a boxy shape.
    EXPECT_GT(Taper(-0.6, -0.6, 0.4).convex_levels(2.0), 1.3);
    EXPECT_GT(Taper(-0.6, -0.6, 0.4).convex_levels(2 / 0.3), 1.8);
}

// A chain knows every level convex for an undeformed convex shape, a taper's levels, and none after a bend, a second
// taper or a twist of cross-sections that are not round.
TEST(SuperquadricDeformation, TheChainsConvexLevels) {
    const Vec3d radii{0.5, 0.6, 0.7};
    EXPECT_TRUE(std::isinf(DeformationChain(Superellipsoid(radii, 1, 1)).convex_levels()));
    EXPECT_EQ(DeformationChain(Superellipsoid(radii, 2.5, 1)).convex_levels(), 0.0);
    DeformationChain tapered(Superellipsoid(radii, 1, 0.5));
    tapered.append(Taper(-0.6, -0.6, radii.z));
    EXPECT_EQ(tapered.convex_levels(), Taper(-0.6, -0.6, radii.z).convex_levels(2.0));
    EXPECT_GT(tapered.convex_levels(), 1.0);
    // Two rates change the cross-sections' shape with the height: no level is known convex.
    DeformationChain two_rates(Superellipsoid(radii, 1, 0.5));
    two_rates.append(Taper(-0.6, 0.4, radii.z));
    EXPECT_EQ(two_rates.convex_levels(), 0.0);
    // A twist keeps them where the cross-sections are round (the level sets are solids of revolution about z),
    // before a taper or after one, and loses them otherwise.
    DeformationChain twisted = tapered;
    twisted.append(Twist(1.0, radii.z));
    EXPECT_EQ(twisted.convex_levels(), 0.0);
    const Superellipsoid round({0.5, 0.5, 0.7}, 0.4, 1);
    DeformationChain turned(round);
    turned.append(Twist(1.0, 0.7));
    EXPECT_TRUE(std::isinf(turned.convex_levels()));
    turned.append(Taper(-0.6, -0.6, 0.7));
    EXPECT_EQ(turned.convex_levels(), Taper(-0.6, -0.6, 0.7).convex_levels(2 / 0.4));
    turned.append(Twist(-2.0, 0.7));
    EXPECT_EQ(turned.convex_levels(), Taper(-0.6, -0.6, 0.7).convex_levels(2 / 0.4));
    turned.append(Taper(0.3, 0.3, 0.7));
    EXPECT_EQ(turned.convex_levels(), 0.0);  // a second taper: the profile is no longer the shape's own
    DeformationChain bent(round);
    bent.append(Bend(1.0, 0.3, 0.0, {-0.7, 0.7}));
    EXPECT_EQ(bent.convex_levels(), 0.0);
    DeformationChain star(Superellipsoid(radii, 3, 1));
    star.append(Taper(-0.6, -0.6, radii.z));
    EXPECT_EQ(star.convex_levels(), 0.0);
}

}  // namespace
}  // namespace isotrace
