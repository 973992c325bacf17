#include "geometry/implicit/sphere_prefilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "renderer/core/inline_vector.h"

namespace isotrace {
namespace {

// Passes the spheres whose radius exceeds a level.
struct RadiusAbove {
    float level;
    unsigned test(const SphereLanes& s) const { return lane_bits(s.radius > level); }
};

TEST(SpherePrefilter, AppendNearKeepsThePassingElementsInListOrderAfterWhatWasThere) {
    std::mt19937 random(5);
    std::uniform_real_distribution<float> unit(0, 1);
    std::vector<BoundingSphere> spheres(200);
    for (BoundingSphere& s : spheres) s = {{unit(random), unit(random), unit(random)}, unit(random)};
    for (std::size_t count = 0; count <= 70; ++count) {  // every tail length, and past the inline capacity
        std::vector<std::uint32_t> listed;
        for (std::size_t i = 0; i < count; ++i) listed.push_back(std::uint32_t(random() % spheres.size()));
        InlineVector<std::uint32_t, 8> out;
        out.push_back(12345);
        append_near(listed, spheres, RadiusAbove{0.5f}, out);
        std::vector<std::uint32_t> expected{12345};
        for (std::uint32_t id : listed)
            if (spheres[id].radius > 0.5f) expected.push_back(id);
        ASSERT_EQ(std::vector<std::uint32_t>(out.begin(), out.end()), expected) << count << " listed";
    }
}

// The float test may keep spheres the segment misses, never drop one it meets: checked against the exact distance
// in double from random segments to random spheres, many of them just touching.
TEST(SpherePrefilter, SegmentTestNeverDropsASphereTheSegmentMeets) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-50, 50), unit(-1, 1), half_length(0, 20),
        radius(0.01, 3);
    std::vector<BoundingSphere> spheres;
    std::vector<std::uint32_t> ids;
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3d p(coordinate(random), coordinate(random), coordinate(random));
        Vec3d u(unit(random), unit(random), unit(random));
        if (length(u) < 1e-3) continue;
        u = normalize(u);
        const double half = half_length(random);
        spheres.clear();
        ids.clear();
        double centre_bound = 0;
        for (std::uint32_t k = 0; k < 8; ++k) {
            // A sphere whose surface passes at distance ≈ r from a random point of the segment.
            const double r = radius(random);
            const Vec3d on_segment = p + u * (half * unit(random));
            Vec3d away(unit(random), unit(random), unit(random));
            away = normalize(away);
            const Vec3d centre = on_segment + away * (r * (1 - 1e-7));
            const BoundingSphere s{{float(centre.x), float(centre.y), float(centre.z)}, float(r)};
            spheres.push_back(s);
            ids.push_back(k);
            centre_bound = std::max(centre_bound, length(Vec3d(s.centre[0], s.centre[1], s.centre[2])));
        }
        InlineVector<std::uint32_t, 8> near;
        append_near(ids, spheres, SegmentNearSpheres(p, u, half, centre_bound), near);
        for (std::uint32_t k : ids) {
            const BoundingSphere& s = spheres[k];
            const Vec3d c(s.centre[0], s.centre[1], s.centre[2]);
            const double along = std::clamp(dot(c - p, u), -half, half);
            if (length(p + u * along - c) > double(s.radius)) continue;  // the segment misses it
            EXPECT_NE(std::find(near.begin(), near.end(), k), near.end()) << "trial " << trial << ", sphere " << k;
        }
    }
}

}  // namespace
}  // namespace isotrace
