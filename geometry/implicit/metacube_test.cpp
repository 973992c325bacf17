// The metacube element M = (C, d, R, w), rotated and non-uniform: distance to the box against a brute force over
// its 26 faces, edges and vertices in world space (including which of the paper's regions is nearest), the
// metaball and hard-cube limits, the single-element rounded-box isosurface, gradients, bounds and validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "geometry/implicit/field_function.h"
#include "geometry/implicit/implicit_test_support.h"
#include "geometry/implicit/metacube.h"
#include "geometry/implicit/nishimura_quadratic.h"

namespace isotrace {
namespace {

double segment_distance_squared(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
    const Vec3d ab = b - a;
    const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    const Vec3d offset = p - (a + ab * t);
    return dot(offset, offset);
}

struct BruteForceDistance {
    double distance_squared;
    int nearest_feature_dimension;  // 2 face, 1 edge, 0 vertex, −1 inside
};

// Distance from p to the solid box as the minimum over its features, each measured in world space: 6 faces (only
// where p projects inside the face), 12 edges (segments) and 8 vertices; 0 when p is behind every face plane.
BruteForceDistance brute_force_distance(const OrientedBox& box, const Vec3d& p) {
    bool inside = true;
    BruteForceDistance best{std::numeric_limits<double>::infinity(), -1};
    // Vertices, then edges, then faces; a later feature must be clearly nearer to win, so that an edge clamped to
    // its end (the vertex, up to rounding) does not claim a vertex-region point.
    auto consider = [&](double d2, int dimension) {
        if (d2 < best.distance_squared * (1 - 1e-9)) best = {d2, dimension};
    };
    for (int corner = 0; corner < 8; ++corner) {
        Vec3d vertex = box.centre;
        for (int k = 0; k < 3; ++k) vertex += box.axes[k] * ((corner >> k & 1 ? 1.0 : -1.0) * box.half_size[k]);
        consider(dot(p - vertex, p - vertex), 0);
    }
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        for (double side : {-1.0, 1.0}) {
            const Vec3d normal = box.axes[k] * side;
            const Vec3d face_centre = box.centre + normal * box.half_size[k];
            const double height = dot(p - face_centre, normal);
            if (height > 0) inside = false;
            const Vec3d in_plane = p - normal * height - face_centre;
            if (std::abs(dot(in_plane, box.axes[i])) <= box.half_size[i] &&
                std::abs(dot(in_plane, box.axes[j])) <= box.half_size[j])
                consider(height * height, 2);
            // The face's two edges along axis i; over all faces that is each of the 12 edges once.
            for (double side_j : {-1.0, 1.0}) {
                const Vec3d middle = face_centre + box.axes[j] * (side_j * box.half_size[j]);
                const Vec3d reach = box.axes[i] * box.half_size[i];
                consider(segment_distance_squared(p, middle - reach, middle + reach), 1);
            }
        }
    }
    if (inside) return {0, -1};
    return best;
}

TEST(Metacube, DistanceIsZeroInsideTheBox) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 200; ++i) {
        const Metacube element = random_metacube(rng);
        const OrientedBox box = element.skeleton();
        Vec3d p = box.centre;
        for (int k = 0; k < 3; ++k) p += box.axes[k] * (0.999 * u(rng) * box.half_size[k]);
        EXPECT_LT(element.distance_squared(p), 1e-28);
    }
}

TEST(Metacube, DistanceMatchesBruteForceInFaceEdgeAndVertexRegions) {
    std::mt19937_64 rng(2);
    int regions_seen[4] = {};
    for (int i = 0; i < 5000; ++i) {
        const Metacube element = random_metacube(rng);
        const Vec3d p = element.centre() + random_vector(rng, -2, 2);
        const BruteForceDistance expected = brute_force_distance(element.skeleton(), p);
        const double d2 = element.distance_squared(p);
        EXPECT_NEAR(d2, expected.distance_squared, 1e-12 * (1 + expected.distance_squared));

        // The paper's region vector: the number of axes with |pₖ| > dₖ says face (1), edge (2) or vertex (3).
        const Vec3d local = element.skeleton().to_local(p), d = element.half_size();
        if (std::min({d.x, d.y, d.z}) < 0.05) continue;  // a thin box makes the nearest feature a near tie
        int outside_axes = 0;
        double margin = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k) {
            outside_axes += std::abs(local[k]) > d[k];
            margin = std::min(margin, std::abs(std::abs(local[k]) - d[k]));
        }
        if (margin < 1e-3) continue;
        EXPECT_EQ(expected.nearest_feature_dimension, outside_axes == 0 ? -1 : 3 - outside_axes);
        ++regions_seen[outside_axes];
    }
    for (int count : regions_seen) EXPECT_GT(count, 50);  // inside, face, edge and vertex all exercised
}

TEST(Metacube, ZeroHalfSizeIsAMetaball) {
    std::mt19937_64 rng(3);
    for (int i = 0; i < 200; ++i) {
        const Vec3d centre = random_vector(rng, -2, 2), p = random_vector(rng, -4, 4);
        OrientedBox rotated_point;
        rotated_point.centre = centre;
        rotated_point.axes = random_axes(rng);
        const double expected = dot(p - centre, p - centre);
        EXPECT_DOUBLE_EQ(Metacube::metaball(centre, 1, 1).distance_squared(p), expected);
        EXPECT_NEAR(Metacube(rotated_point, 1, 1).distance_squared(p), expected, 1e-13 * expected);
    }
}

// A lone element's isosurface is the set of points at the kernel's iso-radius ρ from the box: a rounded box.
TEST(Metacube, SingleElementSurfaceIsTheBoxOffsetByTheIsoRadius) {
    std::mt19937_64 rng(4);
    const double threshold = 0.3;
    for (std::string_view name : field_function_names()) {
        const auto kernel = make_field_function(name, 4);
        for (int i = 0; i < 100; ++i) {
            const Metacube element = random_metacube(rng);
            if (element.weight() < 0) continue;
            const double rho = *kernel->iso_radius(element.radius(), element.weight(), threshold);
            // Walk from the nearest box point outwards by ρ (the nearest point is clamping in local coordinates).
            const OrientedBox box = element.skeleton();
            const Vec3d p = box.centre + random_vector(rng, -4, 4);
            Vec3d local = box.to_local(p);
            for (int k = 0; k < 3; ++k) local[k] = std::clamp(local[k], -box.half_size[k], box.half_size[k]);
            const Vec3d nearest = box.centre + box.to_world_vector(local);
            if (length(p - nearest) < 1e-3) continue;
            const Vec3d on_surface = nearest + normalize(p - nearest) * rho;
            EXPECT_NEAR(element.field(*kernel, on_surface), threshold, 1e-11) << name;
        }
    }
}

TEST(Metacube, GradientMatchesFiniteDifferences) {
    std::mt19937_64 rng(5);
    for (std::string_view name : field_function_names()) {
        const auto kernel = make_field_function(name, 4);
        int checked = 0;
        for (int i = 0; i < 400; ++i) {
            const Metacube element = random_metacube(rng);
            const Vec3d p = element.centre() + random_vector(rng, -2.5, 2.5);
            const double r2 = element.distance_squared(p), radius2 = element.radius() * element.radius();
            // Away from the support edge (Blinn's kink) and from Nishimura's breakpoint (C¹ only).
            if (r2 > 0.95 * radius2 || std::abs(r2 / radius2 - NishimuraQuadratic::kUnitBreakpoint) < 0.01) continue;
            const double h = 1e-6;
            const Vec3d gradient = element.field_gradient(*kernel, p);
            for (int k = 0; k < 3; ++k) {
                Vec3d step;
                step[k] = h;
                const double numeric = (element.field(*kernel, p + step) - element.field(*kernel, p - step)) / (2 * h);
                EXPECT_NEAR(gradient[k], numeric, 1e-6 * (1 + std::abs(numeric))) << name << " axis " << k;
            }
            ++checked;
        }
        EXPECT_GT(checked, 50) << name;
    }
}

TEST(Metacube, FieldAndGradientVanishOutsideTheSupport) {
    const auto kernel = make_field_function("kim", 0);
    const Metacube element = Metacube::metaball({1, 2, 3}, 0.5, 2);
    EXPECT_EQ(element.field(*kernel, {1, 2, 3.6}), 0);
    EXPECT_EQ(element.field_gradient(*kernel, {1, 2, 3.6}), Vec3d{});
    EXPECT_DOUBLE_EQ(element.field(*kernel, {1, 2, 3}), 2);
}

TEST(Metacube, HardCubeIsTheClosedBoxWithWeightW) {
    OrientedBox box;
    box.centre = {1, 0, 0};
    box.half_size = {1, 0.5, 0.25};
    const Metacube cube(box, 0, 3);
    const auto kernel = make_field_function("kim", 0);
    EXPECT_TRUE(cube.is_hard_cube());
    EXPECT_FALSE(Metacube(box, 0.1, 3).is_hard_cube());
    EXPECT_EQ(cube.field(*kernel, {1.5, 0.2, 0.1}), 3);
    EXPECT_EQ(cube.field(*kernel, {2, 0.5, 0.25}), 3);  // on a corner: the box is closed
    EXPECT_EQ(cube.field(*kernel, {2.001, 0, 0}), 0);
    EXPECT_EQ(cube.field_gradient(*kernel, {1.5, 0.2, 0.1}), Vec3d{});
    const WorldBounds bounds = cube.support_bounds();
    EXPECT_EQ(bounds.lower, (Vec3d{0, -0.5, -0.25}));
    EXPECT_EQ(bounds.upper, (Vec3d{2, 0.5, 0.25}));
}

TEST(Metacube, SupportBoundsAreTightAndContainTheSupport) {
    std::mt19937_64 rng(6);
    for (int i = 0; i < 200; ++i) {
        const Metacube element = random_metacube(rng);
        const WorldBounds bounds = element.support_bounds();
        const OrientedBox box = element.skeleton();
        for (int j = 0; j < 3; ++j) {
            // The box vertex furthest along world axis j, pushed R further, is on the support's boundary.
            Vec3d vertex = box.centre;
            for (int k = 0; k < 3; ++k) vertex += box.axes[k] * std::copysign(box.half_size[k], box.axes[k][j]);
            Vec3d extreme = vertex;
            extreme[j] += element.radius();
            EXPECT_NEAR(extreme[j], bounds.upper[j], 1e-12);
            EXPECT_NEAR(element.distance_squared(extreme), element.radius() * element.radius(), 1e-12);
        }
        for (int n = 0; n < 50; ++n) {
            const Vec3d p = box.centre + random_vector(rng, -4, 4);
            if (element.distance_squared(p) > element.radius() * element.radius()) continue;
            for (int j = 0; j < 3; ++j) {
                EXPECT_GE(p[j], bounds.lower[j]);
                EXPECT_LE(p[j], bounds.upper[j]);
            }
        }
    }
}

TEST(Metacube, SquaredDistanceRangeBoundsEveryPointOfTheBox) {
    // Random elements (metaballs, rotated metacubes, flat skeletons) and random boxes near them: dist² of every
    // sampled point lies between the nearest and the farthest bound, and the farthest bound is reached at a corner.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 400; ++i) {
        const Metacube element = random_metacube(rng);
        const Vec3d corner = element.centre() + random_vector(rng, -3, 2);
        const WorldBounds box{corner, corner + random_vector(rng, 0.05, 1.5)};
        const double nearest = element.nearest_squared_distance(box);
        const double farthest = element.farthest_squared_distance(box);
        ASSERT_LE(nearest, farthest);
        for (int n = 0; n < 200; ++n) {
            const Vec3d p = box.lower + (box.upper - box.lower) * Vec3d{u(rng), u(rng), u(rng)};
            const double d2 = element.distance_squared(p);
            EXPECT_GE(d2, nearest * (1 - 1e-12)) << "element " << i;
            EXPECT_LE(d2, farthest * (1 + 1e-12)) << "element " << i;
        }
        double at_corners = 0;
        for (int c = 0; c < 8; ++c)
            at_corners = std::max(at_corners, element.distance_squared({(c & 1 ? box.upper : box.lower).x,
                                                                        (c & 2 ? box.upper : box.lower).y,
                                                                        (c & 4 ? box.upper : box.lower).z}));
        EXPECT_NEAR(farthest, at_corners, 1e-12 * (1 + at_corners)) << "element " << i;
    }
}

TEST(Metacube, SquaredDistanceRangeOfAMetaballIsExact) {
    // The nearest point of the box [1, 2]×[0, 1]×[−1, 1] to the centre 0 is (1, 0, 0), the farthest a corner.
    const Metacube ball = Metacube::metaball({0, 0, 0}, 3, -2);
    const WorldBounds box{{1, 0, -1}, {2, 1, 1}};
    EXPECT_EQ(ball.nearest_squared_distance(box), 1);
    EXPECT_EQ(ball.farthest_squared_distance(box), 6);
    EXPECT_EQ(ball.nearest_squared_distance({{-1, -1, -1}, {1, 1, 1}}), 0);  // the centre is inside
}

// The frame is stored as a quaternion (96 bytes per element): the world axes come back exactly, so axis-aligned
// boxes compute exactly as before; a rotated frame comes back within rounding.
TEST(Metacube, FrameKeptAsAQuaternionComesBackExactOrWithinRounding) {
    OrientedBox aligned;
    aligned.centre = {0.25, -1, 3};
    aligned.half_size = {0.5, 1, 2};
    const OrientedBox back = Metacube(aligned, 0.5, 1).skeleton();
    for (int k = 0; k < 3; ++k) EXPECT_EQ(back.axes[k], aligned.axes[k]) << "axis " << k;
    EXPECT_EQ(back.centre, aligned.centre);
    EXPECT_EQ(back.half_size, aligned.half_size);

    std::mt19937_64 rng(37);
    for (int trial = 0; trial < 1000; ++trial) {
        OrientedBox rotated = aligned;
        rotated.axes = random_axes(rng);
        const OrientedBox again = Metacube(rotated, 0.5, 1).skeleton();
        for (int k = 0; k < 3; ++k) EXPECT_LT(length(again.axes[k] - rotated.axes[k]), 4e-15) << "axis " << k;
    }
}

// A quaternion holds no reflection: a mirrored frame is kept as the rotation with its last axis turned round,
// which is the same (symmetric) box, so the field and its gradient do not change.
TEST(Metacube, MirroredFrameIsTheSameBox) {
    std::mt19937_64 rng(41);
    const NishimuraQuadratic kernel;
    for (int trial = 0; trial < 200; ++trial) {
        OrientedBox box;
        box.centre = random_vector(rng, -1, 1);
        box.axes = random_axes(rng);
        box.half_size = random_vector(rng, 0.1, 1);
        OrientedBox mirrored = box;
        mirrored.axes[2] = -box.axes[2];
        const Metacube element(box, 0.8, 1), reflection(mirrored, 0.8, 1);
        for (int point = 0; point < 20; ++point) {
            const Vec3d p = box.centre + random_vector(rng, -2, 2);
            EXPECT_NEAR(reflection.distance_squared(p), element.distance_squared(p), 1e-12);
            EXPECT_LT(length(reflection.field_gradient(kernel, p) - element.field_gradient(kernel, p)), 1e-12);
        }
    }
}

TEST(Metacube, RejectsInvalidParametersNamingTheField) {
    OrientedBox box;
    box.half_size = {1, 1, 1};
    auto with = [](OrientedBox b, auto change) {
        change(b);
        return b;
    };
    expect_invalid_naming([&] { Metacube(box, -1, 1); }, "radius");
    expect_invalid_naming([&] { Metacube(box, NAN, 1); }, "radius");
    expect_invalid_naming([&] { Metacube(box, INFINITY, 1); }, "radius");
    expect_invalid_naming([&] { Metacube::metaball({}, 0, 1); }, "radius");  // R and d both 0
    expect_invalid_naming([&] { Metacube(with(box, [](OrientedBox& b) { b.half_size.z = 0; }), 0, 1); }, "radius");
    expect_invalid_naming([&] { Metacube(box, 1, NAN); }, "weight");
    expect_invalid_naming([&] { Metacube(box, 1, -INFINITY); }, "weight");
    expect_invalid_naming([&] { Metacube(with(box, [](OrientedBox& b) { b.centre.y = NAN; }), 1, 1); }, "centre");
    expect_invalid_naming([&] { Metacube(with(box, [](OrientedBox& b) { b.half_size.x = -0.1; }), 1, 1); }, "half_size");
    expect_invalid_naming([&] { Metacube(with(box, [](OrientedBox& b) { b.half_size.y = INFINITY; }), 1, 1); },
                          "half_size");
    expect_invalid_naming([&] { Metacube(with(box, [](OrientedBox& b) { b.axes[0] = {2, 0, 0}; }), 1, 1); }, "rotation");
    expect_invalid_naming([&] { Metacube(with(box, [](OrientedBox& b) { b.axes[1] = {1, 0, 0}; }), 1, 1); }, "rotation");
    expect_invalid_naming([&] { Metacube(with(box, [](OrientedBox& b) { b.axes[2].z = NAN; }), 1, 1); }, "rotation");
    // Allowed: negative density, zero weight, a hard cube, a mirrored frame.
    EXPECT_NO_THROW(Metacube(box, 1, -2));
    EXPECT_NO_THROW(Metacube(box, 1, 0));
    EXPECT_NO_THROW(Metacube(box, 0, 1));
    EXPECT_NO_THROW(Metacube(with(box, [](OrientedBox& b) { b.axes[2] = {0, 0, -1}; }), 1, 1));
}

}  // namespace
}  // namespace isotrace
