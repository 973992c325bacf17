// The occluded callbacks' loop under the passes of a two-pass occlusion query: a query the primitive puts off is
// asked in the second pass only (and kept by the first, when its ray is the query's own), every other query in the
// first pass only, and every query in a single pass.
#include "renderer/embree/user_geometry.h"

#include <gtest/gtest.h>

#include <limits>

namespace isotrace {
namespace {

struct Asked {
    int first_hits = 0;
    bool blocked = false;
};

int later_asks = 0;
bool block_later(const void*, std::uint32_t, const Vec3d&, const Vec3d&, double, float) {
    ++later_asks;
    return true;
}

// One ray through the loop, with a primitive that puts the query off or not and blocks every ray it is asked; the
// context's own ray is this one unless `copied` (as when Embree hands a callback a copy).
Asked occlude_one(QueryContext& context, bool puts_off, bool copied = false) {
    RTCRay ray{};
    ray.org_x = 0, ray.org_y = 0, ray.org_z = 0, ray.dir_x = 0, ray.dir_y = 0, ray.dir_z = 1;
    ray.tnear = 0, ray.tfar = std::numeric_limits<float>::infinity();
    RTCRay other = ray;
    context.rays = copied ? &other : &ray, context.ray_count = 1;
    int valid = -1;
    RTCOccludedFunctionNArguments args{};
    args.valid = &valid;
    args.context = &context.embree;
    args.ray = reinterpret_cast<RTCRayN*>(&ray);
    args.N = 1;
    Asked asked;
    user_geometry::occlude_rays(
        &args, 0,
        [&](const Vec3d&, const Vec3d&, double, float) {
            ++asked.first_hits;
            return true;
        },
        [&](const Vec3d&, const Vec3d&, double) { return puts_off; }, block_later);
    asked.blocked = ray.tfar == -std::numeric_limits<float>::infinity();
    return asked;
}

TEST(UserGeometryOcclusion, APutOffQueryIsAskedInTheSecondPassOnly) {
    QueryScratchPool pool(1);
    for (const bool puts_off : {false, true}) {
        QueryContext single(pool);
        const Asked once = occlude_one(single, puts_off);
        EXPECT_EQ(once.first_hits, 1);
        EXPECT_TRUE(once.blocked);
        EXPECT_FALSE(single.put_off.any());

        QueryContext two_pass(pool);
        two_pass.occlusion_pass = OcclusionPass::AwayFromStarts;
        const Asked first = occlude_one(two_pass, puts_off);
        EXPECT_EQ(first.first_hits, puts_off ? 0 : 1) << puts_off;
        EXPECT_EQ(first.blocked, !puts_off);
        EXPECT_EQ(two_pass.put_off.any(), puts_off);
        two_pass.occlusion_pass = OcclusionPass::AtStarts;
        const Asked second = occlude_one(two_pass, puts_off);
        EXPECT_EQ(second.first_hits, puts_off ? 1 : 0) << puts_off;
        EXPECT_EQ(second.blocked, puts_off);
    }
}

// A query put off with the query's own ray is kept and asked without a second traversal, on its own lane only; one
// whose ray is a copy is not kept, and the query traverses the scene again.
TEST(UserGeometryOcclusion, PutOffQueriesAreKeptForTheirOwnRays) {
    QueryScratchPool pool(1);
    QueryContext kept(pool);
    kept.occlusion_pass = OcclusionPass::AwayFromStarts;
    occlude_one(kept, true);
    ASSERT_TRUE(kept.put_off.any());
    EXPECT_TRUE(kept.put_off.all_kept());
    later_asks = 0;
    EXPECT_EQ(kept.put_off.ask(0u), 0u);  // its lane is not open
    EXPECT_EQ(later_asks, 0);
    EXPECT_EQ(kept.put_off.ask(1u), 1u);
    EXPECT_EQ(later_asks, 1);

    QueryContext copied(pool);
    copied.occlusion_pass = OcclusionPass::AwayFromStarts;
    occlude_one(copied, true, true);
    EXPECT_TRUE(copied.put_off.any());
    EXPECT_FALSE(copied.put_off.all_kept());
}

// More queries put off than the list keeps: the first pass notes that not all were kept.
TEST(UserGeometryOcclusion, PutOffQueriesBeyondTheListAreNotKept) {
    QueryScratchPool pool(1);
    QueryContext context(pool);
    context.occlusion_pass = OcclusionPass::AwayFromStarts;
    for (unsigned k = 0; k < PutOffQueries::kMostKept; ++k) occlude_one(context, true);
    EXPECT_TRUE(context.put_off.all_kept());
    occlude_one(context, true);
    EXPECT_FALSE(context.put_off.all_kept());
}

}  // namespace
}  // namespace isotrace
