#include "renderer/plugin/surface_hit.h"

#include <gtest/gtest.h>

#include "renderer/plugin/scene_object.h"

namespace isotrace {
namespace {

TEST(SurfaceHit, IsPlacedByItsObjectItsRecordOrNothing) {
    std::optional<Transform> computed;
    SurfaceHit hit;
    EXPECT_TRUE(hit.to_world(computed).is_identity());  // no object: world space

    SceneObject object;
    object.to_world = Transform::translate({1, 2, 3});
    hit.object = &object;
    EXPECT_EQ(&hit.to_world(computed), &object.to_world);  // the object's own, not a copy
    EXPECT_FALSE(computed);

    const PlacementRecord record = *placement_record(Transform::scale({2, 2, 2}), 0);
    hit.placement = &record;
    EXPECT_EQ(hit.to_world(computed).point(Vec3d(1, 1, 1)), Vec3d(2, 2, 2));
    EXPECT_TRUE(computed);
}

TEST(SurfaceHit, HoldsNoTransform) {
    // Hits are built and passed once per ray: a Transform (256 bytes) in them was copied several times per hit.
    EXPECT_LT(sizeof(SurfaceHit), sizeof(Transform));
}

}  // namespace
}  // namespace isotrace
