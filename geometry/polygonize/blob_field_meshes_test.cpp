// Blob fields that used to give broken meshes or misleading figures: metaballs that touch at a saddle of the field
// (origin correction had no gradient to follow), options that do not apply to a method.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/implicit/blob_group_shape.h"
#include "geometry/polygonize/mesh_topology.h"
#include "geometry/polygonize/polygonize_field.h"
#include "geometry/polygonize/spherical_origin.h"

namespace isotrace {
namespace {

constexpr double kThreshold = 0.5;

// Two equal Kim metaballs (R = 2, w = 1) whose surfaces meet at the origin: each contributes T/2 there,
// (1 − d²/R²)³ = 1/4; scaled by `gap` (1: touching, slightly more: nearly touching, slightly less: a thin neck).
// The field is kept by the shape it came from.
struct TouchingBalls {
    explicit TouchingBalls(double gap)
        : shape(BlobGroup({Metacube::metaball({-distance(gap), 0, 0}, 2, 1), Metacube::metaball({distance(gap), 0, 0}, 2, 1)},
                          make_field_function("kim", 4.0), kThreshold)),
          field(shape.implicit_field()) {}
    static double distance(double gap) { return gap * 2 * std::sqrt(1 - std::cbrt(0.25)); }
    BlobGroupShape shape;
    std::unique_ptr<ImplicitField> field;
};

PolygonizeOptions spherical(int depth) {
    PolygonizeOptions options;
    options.method = PolygonizeMethod::SphericalDualContouring;
    options.depth = depth;
    return options;
}

// The default origin is the saddle between the balls, where ∇f = 0: the origin has to leave it along a direction
// found by probing, and the mesh must close (before, 0 steps were taken and the mesh had 56 to 208 open edges).
TEST(BlobFieldMeshes, TouchingMetaballsGiveClosedSphericalMeshes) {
    for (double gap : {1.0, 1 + 1e-9, 1 - 1e-9, 1 + 1e-6, 1 - 1e-6}) {
        const TouchingBalls balls(gap);
        const OriginCorrection correction = correct_origin(*balls.field, {0, 0, 0}, 5);
        EXPECT_TRUE(correction.converged) << gap;
        EXPECT_GT(correction.steps, 0) << gap;
        for (int depth = 4; depth <= 6; ++depth) {
            const Polygonization p = polygonize_field(*balls.field, spherical(depth));
            EXPECT_TRUE(is_closed_two_manifold(p.mesh)) << gap << " depth " << depth;
            EXPECT_GT(p.report.origin_steps, 0) << gap << " depth " << depth;
        }
    }
}

// Where the origin cannot get clear of the surface by two cells (cells as large as the balls), the polygoniser
// says so instead of returning a mesh with holes.
TEST(BlobFieldMeshes, AnOriginThatCannotBeCorrectedIsAnError) {
    const TouchingBalls balls(1.0);
    try {
        polygonize_field(*balls.field, spherical(3));
        FAIL() << "no error";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()).rfind("origin: (0, 0, 0) could not be moved clear of the surface", 0), 0u)
            << error.what();
    }
    // Without correction the holes are the asked-for result, counted in the report.
    PolygonizeOptions options = spherical(5);
    options.correct_origin = false;
    const Polygonization uncorrected = polygonize_field(*balls.field, options);
    EXPECT_GT(uncorrected.report.edges.boundary, 0u);
}

void expect_error(const PolygonizeOptions& options, const std::string& start) {
    const TouchingBalls balls(1.1);
    try {
        polygonize_field(*balls.field, options);
        ADD_FAILURE() << "no error; expected " << start;
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()).rfind(start, 0), 0u) << error.what();
    }
}

TEST(BlobFieldMeshes, SphericalSettingsForCartesianMethodsAndNanOriginsAreErrors) {
    for (PolygonizeMethod method : {PolygonizeMethod::MarchingCubes, PolygonizeMethod::DualContouring}) {
        PolygonizeOptions options;
        options.method = method;
        options.origin = Vec3d{0, 0, 0};
        expect_error(options, "origin: an origin applies only to spherical-octree dual contouring (sdc)");
        options.origin.reset();
        options.pole_cap = PoleCap::AxisRoot;
        expect_error(options, "pole_cap: the pole cap applies only to spherical-octree dual contouring (sdc)");
        options.pole_cap.reset();
        options.correct_origin = false;
        expect_error(options, "correct_origin: origin correction applies only to spherical-octree dual contouring");
    }
    PolygonizeOptions options = spherical(4);
    options.origin = Vec3d{NAN, 0, 0};
    expect_error(options, "origin: (nan, 0, 0) has a coordinate that is NaN (not a number)");
    options.origin = Vec3d{0, INFINITY, 0};
    expect_error(options, "origin: (0, inf, 0) has a coordinate that is infinite");
}

}  // namespace
}  // namespace isotrace
