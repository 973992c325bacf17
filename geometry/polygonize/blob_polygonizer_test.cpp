#include "geometry/polygonize/blob_polygonizer.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>

#include <numbers>
#include <random>

#include "geometry/implicit/implicit_test_support.h"
#include "geometry/polygonize/mesh_topology.h"

namespace isotrace {
namespace {

constexpr double kThreshold = 0.5;

BlobGroup make_group(std::vector<Metacube> elements) {
    return BlobGroup(std::move(elements), make_field_function("kim", 4.0), kThreshold);
}

// Kim's kernel: a lone ball of radius R and weight w has the sphere of radius R·sqrt(1 − (T/w)^(1/3)).
double kim_iso_radius(double radius, double weight) {
    return radius * std::sqrt(1 - std::cbrt(kThreshold / weight));
}

TEST(Polygonizer, SingleBallVerticesAndNormalsLieOnTheAnalyticSphere) {
    const Vec3d centre(0.3, -0.2, 0.1);
    const double radius = 1.0, weight = 1.0, rho = kim_iso_radius(radius, weight);
    const BlobGroup group = make_group({Metacube::metaball(centre, radius, weight)});
    for (double cells_per_radius : {4.0, 8.0, 16.0}) {
        const TriangleMeshData mesh = polygonize(group, {cell_size_for_smallest_element(group, cells_per_radius)});
        ASSERT_FALSE(mesh.triangles.empty());
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
        double worst = 0, worst_normal = 0;
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const Vec3d offset = Vec3d(mesh.positions[i]) - centre;
            worst = std::max(worst, std::abs(length(offset) - rho));
            worst_normal = std::max(worst_normal, length(Vec3d(mesh.normals[i]) - offset / length(offset)));
        }
        // Vertices are solved on their lattice edges, so only float storage limits them, at every cell size.
        EXPECT_LT(worst, 1e-6 * (1 + length(centre))) << cells_per_radius;
        EXPECT_LT(worst_normal, 1e-5) << cells_per_radius;
    }
}

// The enclosed volume approaches the ball's (the chords cut inside the sphere) as the cells shrink.
TEST(Polygonizer, SingleBallVolumeConvergesFromBelow) {
    const double rho = kim_iso_radius(1.0, 1.0);
    const double exact = 4.0 / 3.0 * std::numbers::pi * rho * rho * rho;
    const BlobGroup group = make_group({Metacube::metaball({0, 0, 0}, 1.0, 1.0)});
    double previous_error = 1;
    for (double cells_per_radius : {4.0, 8.0, 16.0, 32.0}) {
        const TriangleMeshData mesh = polygonize(group, {cell_size_for_smallest_element(group, cells_per_radius)});
        EXPECT_TRUE(is_closed_and_consistently_oriented(mesh)) << cells_per_radius;
        EXPECT_EQ(connected_components(mesh), 1u);
        const double volume = signed_volume(mesh);
        EXPECT_GT(volume, 0) << "triangles face inwards";
        EXPECT_LE(volume, exact * (1 + 1e-6));
        const double error = (exact - volume) / exact;
        EXPECT_LT(error, previous_error) << cells_per_radius;
        if (cells_per_radius >= 8) {
            EXPECT_LT(error, 0.03) << cells_per_radius;
        }
        previous_error = error;
    }
    EXPECT_LT(previous_error, 0.01);
}

TEST(Polygonizer, OverlappingBallsMergeAndDistantBallsDoNot) {
    const TriangleMeshData merged = polygonize(
        make_group({Metacube::metaball({0, 0, 0}, 1, 1), Metacube::metaball({0.8, 0.1, 0}, 1, 1)}), {0.05});
    EXPECT_TRUE(is_closed_and_consistently_oriented(merged));
    EXPECT_EQ(connected_components(merged), 1u);
    const TriangleMeshData apart = polygonize(
        make_group({Metacube::metaball({0, 0, 0}, 1, 1), Metacube::metaball({3, 0, 0}, 1, 1)}), {0.05});
    EXPECT_TRUE(is_closed_and_consistently_oriented(apart));
    EXPECT_EQ(connected_components(apart), 2u);
}

// Rotated non-uniform metacubes, flat skeletons, carving elements: still closed and outward.
TEST(Polygonizer, RandomMetacubeGroupsAreClosedAndOutward) {
    std::mt19937_64 rng(5);
    for (int trial = 0; trial < 4; ++trial) {
        std::vector<Metacube> elements;
        for (int i = 0; i < 12; ++i) elements.push_back(random_metacube(rng));
        const TriangleMeshData mesh = polygonize(make_group(std::move(elements)), {0.12});
        EXPECT_TRUE(is_closed_and_consistently_oriented(mesh)) << trial;
        EXPECT_GT(signed_volume(mesh), 0) << trial;
        mesh.validate("polygonized group");
    }
}

TEST(Polygonizer, HardCubeGivesTheBox) {
    OrientedBox box;
    box.half_size = {0.5, 0.3, 0.2};
    const TriangleMeshData mesh = polygonize(make_group({Metacube(box, 0.0, 1.0)}), {0.05});
    EXPECT_TRUE(is_closed_and_consistently_oriented(mesh));
    for (const Vec3f& p : mesh.positions) {
        const Vec3d q = abs(Vec3d(p));
        EXPECT_LE(std::max({q.x - 0.5, q.y - 0.3, q.z - 0.2}), 1e-6);
    }
}

TEST(Polygonizer, SameMeshForAnyThreadCount) {
    std::mt19937_64 rng(9);
    std::vector<Metacube> elements;
    for (int i = 0; i < 20; ++i) elements.push_back(random_metacube(rng));
    const BlobGroup group = make_group(std::move(elements));
    const auto run = [&](int threads) {
        tbb::task_arena arena(threads);
        return arena.execute([&] { return polygonize(group, {0.1}); });
    };
    const TriangleMeshData one = run(1), two = run(2);
    ASSERT_FALSE(one.triangles.empty());
    EXPECT_EQ(one.triangles, two.triangles);
    EXPECT_EQ(one.positions, two.positions);
    EXPECT_EQ(one.normals, two.normals);
}

TEST(Polygonizer, BelowThresholdGivesNoTriangles) {
    EXPECT_TRUE(polygonize(make_group({Metacube::metaball({0, 0, 0}, 1, 0.4)}), {0.1}).triangles.empty());
}

TEST(Polygonizer, RejectsBadCellSizes) {
    const BlobGroup group = make_group({Metacube::metaball({0, 0, 0}, 1, 1)});
    for (double bad : {0.0, -1.0, std::nan(""), 1e-9})
        expect_invalid_naming([&] { polygonize(group, {bad}); }, "cell_size");
    expect_invalid_naming([&] { cell_size_for_smallest_element(group, 0); }, "cells_per_radius");
    // Within the per-axis limit, but a billion bricks for a crowd of large elements.
    std::vector<Metacube> crowd;
    for (int i = 0; i < 100; ++i) crowd.push_back(Metacube::metaball({0.01 * i, 0, 0}, 1, 1));
    expect_invalid_naming([&] { polygonize(make_group(std::move(crowd)), {2e-5}); }, "cell_size");
}

}  // namespace
}  // namespace isotrace
