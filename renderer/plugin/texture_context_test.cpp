#include <gtest/gtest.h>

#include "renderer/plugin/texture.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {
namespace {

SurfaceHit hit_at(const Vec3f& p, const Vec3f& n) {
    SurfaceHit hit;
    hit.position = p;
    hit.shading_normal = hit.geometric_normal = n;
    hit.uv = {0.25f, 0.5f};
    hit.footprint = 0.3f;
    return hit;
}

void expect_near(const Vec3f& a, const Vec3f& b) {
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
    EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(TextureContext, WithoutAnObjectObjectSpaceIsWorldSpace) {
    const TextureContext context(hit_at({1, 2, 3}, {0, 1, 0}));
    EXPECT_EQ(context.object_position, Vec3f(1, 2, 3));
    EXPECT_EQ(context.object_normal, Vec3f(0, 1, 0));
    EXPECT_EQ(context.shape_position, Vec3d(1, 2, 3));
    EXPECT_EQ(context.object_footprint, 0.3f);
    EXPECT_EQ(context.uv[0], 0.25f);
    EXPECT_EQ(context.shape, nullptr);
}

TEST(TextureContext, ObjectSpaceUndoesThePlacement) {
    SceneObject object;
    // Scaled by 2 (x by 4: the normal's object-space direction changes) and moved up by 10.
    object.to_world = Transform::translate({0, 10, 0}) * Transform::scale({4, 2, 2});
    SurfaceHit hit = hit_at({4, 12, 0}, normalize(Vec3f(1, 1, 0)));
    hit.object = &object;
    object.instanced = true;
    const TextureContext instanced(hit);
    expect_near(instanced.object_position, {1, 1, 0});
    // Object normal ∝ M^T n: (4, 2, 0) / sqrt(2), normalised.
    expect_near(instanced.object_normal, normalize(Vec3f(2, 1, 0)));
    EXPECT_NEAR(instanced.shape_position.x, 1, 1e-6);  // the shape lives in object space
    EXPECT_NEAR(instanced.object_footprint, 0.3f / std::cbrt(16.0f), 1e-6);
    EXPECT_EQ(instanced.position, Vec3f(4, 12, 0));
    object.instanced = false;
    const TextureContext baked(hit);
    EXPECT_EQ(baked.shape_position, Vec3d(Vec3f(4, 12, 0)));  // baked into world space
    EXPECT_EQ(baked.shape_normal, Vec3d(hit.shading_normal));
    expect_near(baked.object_position, {1, 1, 0});
}

TEST(TextureContext, APlacedCopyIsPlacedByItsRecordNotByTheSharedObject) {
    SceneObject shared;  // the copies' object: identity to_world
    shared.instanced = true;
    const PlacementRecord record = *placement_record(Transform::translate({0, 10, 0}) * Transform::scale({2, 2, 2}), 0);
    SurfaceHit hit = hit_at({2, 12, 0}, {1, 0, 0});
    hit.object = &shared;
    hit.placement = &record;
    const TextureContext context(hit);
    expect_near(context.object_position, {1, 1, 0});
    EXPECT_NEAR(context.object_footprint, 0.15f, 1e-6);
}

}  // namespace
}  // namespace isotrace
