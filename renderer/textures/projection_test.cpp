#include "renderer/textures/projection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

TextureContext at_point(const Vec3f& p, const Vec3f& n = {0, 0, 1}) {
    TextureContext context;
    context.position = context.object_position = p;
    context.normal = context.object_normal = n;
    return context;
}

void expect_point(const ProjectedLookups& lookups, int i, float u, float v, float tolerance = 1e-6f) {
    EXPECT_NEAR(lookups.points[std::size_t(i)].point.x, u, tolerance);
    EXPECT_NEAR(lookups.points[std::size_t(i)].point.y, v, tolerance);
    EXPECT_EQ(lookups.points[std::size_t(i)].point.z, 0.0f);
}

TEST(Projection, UvIsTheSurfacesUvAndItsFootprintFollowsTheStretch) {
    const Projection uv({.kind = ProjectionKind::Uv});
    TextureContext context = at_point({5, 6, 7});
    context.uv = {0.25f, 0.75f};
    context.dpdu = {4, 0, 0};  // u changes 1 over 4 world units
    context.dpdv = {0, 0.5f, 0};
    context.footprint = 0.1f;
    const ProjectedLookups lookups = uv.project(context);
    ASSERT_EQ(lookups.count, 1);
    expect_point(lookups, 0, 0.25f, 0.75f);
    EXPECT_FLOAT_EQ(lookups.footprint[0], 0.1f / 4);
    EXPECT_FLOAT_EQ(lookups.footprint[1], 0.1f / 0.5f);
    EXPECT_TRUE(uv.needs().uv);
    context.dpdu = {};  // no uv derivatives: no filtering rather than a division by zero
    EXPECT_EQ(uv.project(context).footprint[0], 0.0f);
}

TEST(Projection, SolidIsThePointAndPlanarDropsTheAxis) {
    const Vec3f p{1, 2, 3};
    const ProjectedLookups solid = Projection({.kind = ProjectionKind::Solid}).project(at_point(p));
    EXPECT_EQ(solid.points[0].point, p);
    expect_point(Projection({.kind = ProjectionKind::Planar, .axis = 2}).project(at_point(p)), 0, 1, 2);
    expect_point(Projection({.kind = ProjectionKind::Planar, .axis = 0}).project(at_point(p)), 0, 2, 3);
    expect_point(Projection({.kind = ProjectionKind::Planar, .axis = 1}).project(at_point(p)), 0, 3, 1);
    EXPECT_FALSE(Projection({.kind = ProjectionKind::Planar}).needs().uv);
}

TEST(Projection, ObjectOrWorldSpace) {
    TextureContext context = at_point({1, 2, 3});
    context.object_position = {-1, -2, -3};
    context.footprint = 2;
    context.object_footprint = 0.5f;
    const ProjectedLookups object = Projection({.kind = ProjectionKind::Solid}).project(context);
    EXPECT_EQ(object.points[0].point, Vec3f(-1, -2, -3));
    EXPECT_EQ(object.footprint[0], 0.5f);
    const ProjectedLookups world = Projection({.kind = ProjectionKind::Solid, .object_space = false}).project(context);
    EXPECT_EQ(world.points[0].point, Vec3f(1, 2, 3));
    EXPECT_EQ(world.footprint[0], 2.0f);
}

TEST(Projection, SphericalAboutY) {
    const Projection spherical({.kind = ProjectionKind::Spherical, .axis = 1});
    expect_point(spherical.project(at_point({0, 0, 2})), 0, 0.5f, 0.5f);    // +z: the seam's opposite, the equator
    expect_point(spherical.project(at_point({3, 0, 0})), 0, 0.75f, 0.5f);   // a quarter turn towards +x
    expect_point(spherical.project(at_point({0, 0, -1})), 0, 1.0f, 0.5f);   // the seam
    expect_point(spherical.project(at_point({0, 5, 0})), 0, 0.5f, 1.0f);    // the +y pole
    expect_point(spherical.project(at_point({1, -1, 0})), 0, 0.75f, 0.25f);  // 45 degrees below the equator
    expect_point(spherical.project(at_point({0, 0, 0})), 0, 0.5f, 0.5f);    // the centre: defined, not NaN
}

TEST(Projection, CylindricalAboutZ) {
    const Projection cylindrical({.kind = ProjectionKind::Cylindrical, .axis = 2});
    // About z the angle is measured from +x towards +y; v is the height along z.
    expect_point(cylindrical.project(at_point({2, 0, 1.5f})), 0, 0.5f, 1.5f);
    expect_point(cylindrical.project(at_point({0, 2, -4})), 0, 0.75f, -4);
    TextureContext context = at_point({2, 0, 0});
    context.object_footprint = 0.1f;
    const ProjectedLookups lookups = cylindrical.project(context);
    EXPECT_NEAR(lookups.footprint[0], 0.1f / (2 * 3.14159265f * 2), 1e-8);  // one turn is 2 pi r long
    EXPECT_FLOAT_EQ(lookups.footprint[1], 0.1f);
}

TEST(Projection, TransformPlacesTheTexture) {
    // The texture scaled by 2 and moved by (1, 0, 0): the point (3, 2, 0) is at texture point (1, 1, 0).
    const Transform placement = Transform::translate({1, 0, 0}) * Transform::scale({2, 2, 2});
    TextureContext context = at_point({3, 2, 0});
    context.object_footprint = 1;
    const ProjectedLookups solid = Projection({.kind = ProjectionKind::Solid, .placement = placement}).project(context);
    EXPECT_NEAR(solid.points[0].point.x, 1, 1e-6);
    EXPECT_NEAR(solid.points[0].point.y, 1, 1e-6);
    EXPECT_NEAR(solid.footprint[0], 0.5f, 1e-6);  // the texture is twice as large: the footprint covers half
    // uv placements act in the uv plane.
    TextureContext surface;
    surface.uv = {0.5f, 0.25f};
    const ProjectedLookups uv =
        Projection({.kind = ProjectionKind::Uv, .placement = Transform::rotate({0, 0, 1}, 90)}).project(surface);
    expect_point(uv, 0, 0.25f, -0.5f);
}

TEST(Projection, TriplanarWeightsSumToOneAndFollowTheNormal) {
    const Projection triplanar({.kind = ProjectionKind::Triplanar, .sharpness = 4});
    for (const Vec3f n : {Vec3f(0, 0, 1), Vec3f(0.6f, 0.8f, 0), normalize(Vec3f(1, -2, 3)), Vec3f(0, 0, 0)}) {
        const ProjectedLookups lookups = triplanar.project(at_point({1, 2, 3}, n));
        ASSERT_EQ(lookups.count, 3);
        EXPECT_NEAR(lookups.points[0].weight + lookups.points[1].weight + lookups.points[2].weight, 1, 1e-6);
    }
    const ProjectedLookups facing_z = triplanar.project(at_point({1, 2, 3}, {0, 0, -1}));
    EXPECT_EQ(facing_z.points[2].weight, 1.0f);
    expect_point(facing_z, 2, 1, 2);  // the z lookup is the planar one along z
    expect_point(facing_z, 0, 2, 3);
    const ProjectedLookups diagonal = triplanar.project(at_point({1, 2, 3}, normalize(Vec3f(1, 1, 0))));
    EXPECT_NEAR(diagonal.points[0].weight, 0.5f, 1e-6);
    EXPECT_NEAR(diagonal.points[1].weight, 0.5f, 1e-6);
}

TEST(Projection, TriplanarIsSeamlessWhereTheDominantAxisSwitches) {
    const Projection triplanar({.kind = ProjectionKind::Triplanar, .sharpness = 8});
    // A value that differs on every plane (each lookup's u): blended, it must not jump as the normal crosses the
    // diagonal between x and y.
    const auto blended = [&](const Vec3f& n) {
        const ProjectedLookups lookups = triplanar.project(at_point({0.3f, 0.7f, 0.1f}, n));
        float sum = 0;
        for (int i = 0; i < 3; ++i) sum += lookups.points[std::size_t(i)].point.x * lookups.points[std::size_t(i)].weight;
        return sum;
    };
    const float e = 1e-4f;
    const float below = blended(normalize(Vec3f(1, 1 - e, 0))), above = blended(normalize(Vec3f(1 - e, 1, 0)));
    EXPECT_NEAR(below, above, 1e-3f);
    EXPECT_GT(std::abs(blended({1, 0, 0}) - blended({0, 1, 0})), 0.1f);  // the planes do differ
}

TEST(Projection, ParsedFromStringsAndObjects) {
    const testing::ParsedScene scene(R"({"a": "triplanar", "b": {"type": "planar", "axis": "x", "space": "world",
        "transform": {"scale": 2}}, "c": {"type": "spherical", "axs": "x"}, "d": "sphercal"})");
    const SceneNode& root = scene.root();
    EXPECT_EQ(parse_projection(root, "a", ProjectionKind::Uv).project(at_point({1, 2, 3})).count, 3);
    TextureContext context = at_point({0, 0, 0});
    context.position = {4, 6, 8};
    expect_point(parse_projection(root, "b", ProjectionKind::Uv).project(context), 0, 3, 4);
    EXPECT_TRUE(parse_projection(root, "missing", ProjectionKind::Uv).needs().uv);
    try {
        parse_projection(root, "c", ProjectionKind::Uv);
        ADD_FAILURE() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("did you mean \"axis\""), std::string::npos) << error.what();
        EXPECT_EQ(error.field(), "c.axs");
    }
    try {
        parse_projection(root, "d", ProjectionKind::Uv);
        ADD_FAILURE() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("did you mean \"spherical\""), std::string::npos) << error.what();
        EXPECT_EQ(error.location().line, 2);
    }
}

}  // namespace
}  // namespace isotrace
