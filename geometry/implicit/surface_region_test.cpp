// surface_region: analytic regions of a lone metaball and a hard cube, and on random groups of every kernel (with
// carving elements) every sign change of the field found by dense sampling along random lines lies inside its
// cell's region; a cell without a region has none.
#include "geometry/implicit/surface_region.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/implicit/blob_cells.h"
#include "geometry/implicit/implicit_test_support.h"

namespace isotrace {
namespace {

bool inside(const WorldBounds& box, const Vec3d& p, double slack) {
    for (int k = 0; k < 3; ++k)
        if (p[k] < box.lower[k] - slack || p[k] > box.upper[k] + slack) return false;
    return true;
}

TEST(SurfaceRegion, LoneMetaballRegionIsItsIsoSphereBoundsWithinOneSubBox) {
    const auto kernel = make_field_function("wyvill", 0);
    const std::vector<Metacube> ball{Metacube::metaball({0, 0, 0}, 1, 1)};
    const std::uint32_t id = 0;
    const double threshold = 0.6;
    const double iso = *kernel->iso_radius(1, 1, threshold);
    ASSERT_LT(iso, 0.5);
    // The support's box, halved 12 times: each axis 4 times, sub-boxes of 0.125 per side.
    const auto region = surface_region({{-1, -1, -1}, {1, 1, 1}}, {&id, 1}, ball, *kernel, threshold);
    ASSERT_TRUE(region);
    const Vec3d side{0.125, 0.125, 0.125};
    for (int k = 0; k < 3; ++k) {
        EXPECT_LE(region->lower[k], -iso);
        EXPECT_GE(region->lower[k], -iso - side[k] - 1e-6);  // one sub-box and the padding
        EXPECT_GE(region->upper[k], iso);
        EXPECT_LE(region->upper[k], iso + side[k] + 1e-6);
    }
    // The iso-sphere's radius, 0.396, lies in the sub-boxes from 0.375 to 0.5; those beyond are all outside.
    EXPECT_GT(iso, 0.375);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(region->lower[k], -0.5, 1e-6);
        EXPECT_NEAR(region->upper[k], 0.5, 1e-6);
    }
    // All inside, all outside (but within the support), all beyond the support: no region.
    const double in = iso / 2;
    EXPECT_FALSE(surface_region({{-in, -in, -in}, {in, in, in}}, {&id, 1}, ball, *kernel, threshold));
    EXPECT_FALSE(surface_region({{0.9, 0, 0}, {0.95, 0.05, 0.05}}, {&id, 1}, ball, *kernel, threshold));
    EXPECT_FALSE(surface_region({{2, 2, 2}, {3, 3, 3}}, {&id, 1}, ball, *kernel, threshold));
    // In a blob group the region is the cell's box: a ray through the support but outside the region makes no
    // query; one through the region hits at the iso-sphere.
    const BlobGroup group(ball, make_field_function("wyvill", 0), threshold);
    BlobQueryWork outside, through;
    EXPECT_FALSE(group.first_crossing({0.75, -5, 0}, {0, 1, 0}, 0, 100, outside));
    EXPECT_EQ(outside.queries, 0u);
    const auto hit = group.first_crossing({0, -5, 0}, {0, 1, 0}, 0, 100, through);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5 - iso, 1e-9);
    EXPECT_EQ(through.queries, 1u);
}

// Regression: a lone hard cube's cell is the cube itself, so its surface (the step of its field) lies on the
// cell's faces, where every sub-box is inside the closed cube; the region must still cover the whole cube
// (metacube_gallery lost its hard cube when it did not).
TEST(SurfaceRegion, HardCubeRegionCoversTheCubeWhenTheCellIsTheCube) {
    const auto kernel = make_field_function("kim", 0);
    OrientedBox box;
    box.centre = {3, 1, 1};
    box.half_size = {1, 1, 1};
    const std::vector<Metacube> cube{Metacube(box, 0, 1)};
    const std::uint32_t id = 0;
    const WorldBounds support = cube[0].support_bounds();
    const auto region = surface_region(support, {&id, 1}, cube, *kernel, 0.5);
    ASSERT_TRUE(region);
    EXPECT_EQ(region->lower, support.lower);
    EXPECT_EQ(region->upper, support.upper);
    const BlobGroup group({cube[0]}, make_field_function("kim", 0), 0.5);
    BlobQueryWork work;
    const auto hit = group.first_crossing({3, 1, -5}, {0, 0, 1}, 0, 100, work);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->t, 5);
    EXPECT_TRUE(hit->entering);
}

TEST(SurfaceRegion, EverySignChangeAlongRandomLinesLiesInItsCellsRegion) {
    std::mt19937_64 rng(21);
    for (const std::string_view name : field_function_names()) {
        const BlobGroup group = random_blob_group(80, 7, std::string(name), 6);
        BlobCells cells;  // the cells before restriction: the whole of each kd cell is examined
        cells.build(group.elements());
        std::size_t changes = 0;
        for (const BlobCells::Cell& cell : cells.cells()) {
            const WorldBounds box{cell.lower, cell.upper};
            const auto region =
                surface_region(box, cells.elements_of(cell), group.elements(), group.kernel(), group.threshold());
            const double spacing = length(box.upper - box.lower) / 4000;
            for (int line = 0; line < 24; ++line) {
                // A segment between two random points of the box, sampled every `spacing`.
                std::uniform_real_distribution<double> u(0, 1);
                const Vec3d a = box.lower + (box.upper - box.lower) * Vec3d{u(rng), u(rng), u(rng)};
                const Vec3d b = box.lower + (box.upper - box.lower) * Vec3d{u(rng), u(rng), u(rng)};
                const int samples = int(length(b - a) / spacing) + 2;
                bool was_inside = group.field(a) > group.threshold();
                for (int s = 1; s <= samples; ++s) {
                    const Vec3d p = a + (b - a) * (double(s) / samples);
                    const bool is_inside = group.field(p) > group.threshold();
                    if (is_inside == was_inside) continue;
                    was_inside = is_inside;
                    ++changes;
                    ASSERT_TRUE(region) << name << ": a crossing in a cell without a region";
                    EXPECT_TRUE(inside(*region, p, 2 * spacing)) << name;
                }
            }
        }
        EXPECT_GT(changes, 200u) << name;
    }
}

// The lanes of metaball_surface_region bound the field as ListedElements does, four elements at a time: on random
// clouds of metaballs (a fifth of them carving), for every kernel of one polynomial piece, each cell's region is the
// element-by-element one, or differs by a sub-box the rounding of a bound near T decides.
TEST(SurfaceRegion, MetaballLanesFindTheRegionOfTheElementByElementSearch) {
    std::mt19937_64 rng(5);
    for (const std::string name : {"kim", "wyvill", "murakami"}) {
        const auto kernel = make_field_function(name, 0);
        ASSERT_EQ(kernel->unit_pieces().size(), 1u) << name;
        std::vector<Metacube> balls;
        std::uniform_real_distribution<double> position(-2, 2), radius(0.3, 0.9);
        for (int i = 0; i < 300; ++i)
            balls.push_back(Metacube::metaball({position(rng), position(rng), position(rng)}, radius(rng),
                                               i % 5 == 4 ? -0.6 : 1.0));
        BlobCells cells;
        cells.build(balls);
        std::size_t regions = 0, same = 0;
        for (const BlobCells::Cell& cell : cells.cells()) {
            const WorldBounds box{cell.lower, cell.upper};
            const auto by_element = surface_region(box, cells.elements_of(cell), balls, *kernel, 0.5);
            const auto in_lanes =
                metaball_surface_region(box, cells.elements_of(cell), balls, kernel->unit_pieces()[0], 0.5);
            ASSERT_EQ(by_element.has_value(), in_lanes.has_value()) << name;
            if (!by_element) continue;
            ++regions;
            same += by_element->lower == in_lanes->lower && by_element->upper == in_lanes->upper;
            const Vec3d sub_box = (box.upper - box.lower) / 16.0;
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(in_lanes->lower[k], by_element->lower[k], sub_box[k] * 1.001) << name;
                EXPECT_NEAR(in_lanes->upper[k], by_element->upper[k], sub_box[k] * 1.001) << name;
            }
        }
        EXPECT_GT(regions, 100u) << name;
        EXPECT_GE(double(same), 0.99 * double(regions)) << name;
    }
}

}  // namespace
}  // namespace isotrace
