#include "geometry/polygonize/blob_field_grid.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/implicit/implicit_test_support.h"

namespace isotrace {
namespace {

BlobGroup random_group(std::mt19937_64& rng, int count) {
    std::vector<Metacube> elements;
    for (int i = 0; i < count; ++i) elements.push_back(random_metacube(rng));
    return BlobGroup(std::move(elements), make_field_function("kim", 4.0), 0.5);
}

// BlobGroup::field(i, p) is the summed field wherever p lies in element i's support: the grid must agree.
TEST(PolygonizerFieldGrid, MatchesTheGroupsFieldInsideEverySupport) {
    std::mt19937_64 rng(11);
    const BlobGroup group = random_group(rng, 40);
    const BlobFieldGrid grid(group);
    std::uniform_real_distribution<double> u(0, 1);
    int checked = 0;
    for (std::size_t i = 0; i < group.elements().size(); ++i) {
        const WorldBounds b = group.elements()[i].support_bounds();
        for (int s = 0; s < 50; ++s) {
            const Vec3d p = b.lower + (b.upper - b.lower) * Vec3d(u(rng), u(rng), u(rng));
            if (group.elements()[i].distance_squared(p) >= group.elements()[i].radius() * group.elements()[i].radius())
                continue;  // outside element i's support, where field(i, p) may miss elements
            EXPECT_NEAR(grid.field(p), group.field(i, p), 1e-12 * (1 + std::abs(group.field(i, p))));
            const Vec3d g = grid.gradient(p), expected = group.gradient(i, p);
            EXPECT_NEAR(length(g - expected), 0.0, 1e-10 * (1 + length(expected)));
            ++checked;
        }
    }
    EXPECT_GT(checked, 500);
}

TEST(PolygonizerFieldGrid, IsZeroAwayFromEverySupport) {
    const BlobGroup group({Metacube::metaball({0, 0, 0}, 1, 1), Metacube::metaball({5, 0, 0}, 1, 1)},
                          make_field_function("kim", 4.0), 0.5);
    const BlobFieldGrid grid(group);
    EXPECT_EQ(grid.field({2.5, 0, 0}), 0.0);
    EXPECT_EQ(grid.field({-100, 3, 0}), 0.0);
    EXPECT_EQ(grid.field({0, 0, 1e9}), 0.0);
    EXPECT_DOUBLE_EQ(grid.field({5, 0, 0}), 1.0);
}

}  // namespace
}  // namespace isotrace
