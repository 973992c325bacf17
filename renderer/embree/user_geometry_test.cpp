// The occluded callbacks' loop under the passes of a two-pass occlusion query: a query the primitive puts off is
// asked in the second pass only (and noted in the first), every other query in the first pass only, and every
// query in a single pass.
#include "renderer/embree/user_geometry.h"

#include <gtest/gtest.h>

#include <limits>

namespace isotrace {
namespace {

struct Asked {
    int first_hits = 0;
    bool blocked = false;
};

// One ray through the loop, with a primitive that puts the query off or not and blocks every ray it is asked.
Asked occlude_one(QueryContext& context, bool puts_off) {
    RTCRay ray{};
    ray.org_x = 0, ray.org_y = 0, ray.org_z = 0, ray.dir_x = 0, ray.dir_y = 0, ray.dir_z = 1;
    ray.tnear = 0, ray.tfar = std::numeric_limits<float>::infinity();
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
        [&](const Vec3d&, const Vec3d&, double) { return puts_off; });
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
        EXPECT_FALSE(single.put_off);

        QueryContext two_pass(pool);
        two_pass.occlusion_pass = OcclusionPass::AwayFromStarts;
        const Asked first = occlude_one(two_pass, puts_off);
        EXPECT_EQ(first.first_hits, puts_off ? 0 : 1) << puts_off;
        EXPECT_EQ(first.blocked, !puts_off);
        EXPECT_EQ(two_pass.put_off, puts_off);
        two_pass.occlusion_pass = OcclusionPass::AtStarts;
        const Asked second = occlude_one(two_pass, puts_off);
        EXPECT_EQ(second.first_hits, puts_off ? 1 : 0) << puts_off;
        EXPECT_EQ(second.blocked, puts_off);
    }
}

}  // namespace
}  // namespace isotrace
