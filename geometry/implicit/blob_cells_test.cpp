// BlobCells: the cells are disjoint, every element is listed in every cell its support reaches, the walk visits
// a ray's cells in order, point location finds the cell of a point, and coincident elements end the splitting.
#include "geometry/implicit/blob_cells.h"

#include <gtest/gtest.h>

#include <atomic>
#include <random>

#include "geometry/implicit/implicit_test_support.h"

namespace isotrace {
namespace {

bool boxes_overlap_inside(const BlobCells::Cell& a, const BlobCells::Cell& b) {
    for (int k = 0; k < 3; ++k)
        if (!(a.lower[k] < b.upper[k] && b.lower[k] < a.upper[k])) return false;
    return true;
}

std::vector<Metacube> random_elements(int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<Metacube> elements;
    for (int i = 0; i < count; ++i) elements.push_back(random_metacube(rng));
    return elements;
}

TEST(BlobCells, CellsAreDisjointAndListEveryElementTheyMeet) {
    const std::vector<Metacube> elements = random_elements(300, 5);
    BlobCells cells;
    cells.build(elements);
    const auto all = cells.cells();
    ASSERT_GT(all.size(), 8u);
    for (std::size_t i = 0; i < all.size(); ++i)
        for (std::size_t j = i + 1; j < all.size(); ++j) EXPECT_FALSE(boxes_overlap_inside(all[i], all[j]));
    // Points sampled inside each element's support must find it in the list of their cell.
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-1, 1);
    int checked = 0;
    for (std::uint32_t e = 0; e < elements.size(); ++e) {
        const Metacube& element = elements[e];
        for (int s = 0; s < 40; ++s) {
            const Vec3d p = element.centre() + Vec3d{u(rng), u(rng), u(rng)} * (element.radius() * 0.6) +
                            element.skeleton().to_world_vector(element.half_size() * u(rng));
            if (element.distance_squared(p) >= element.radius() * element.radius()) continue;
            const auto near = cells.elements_near(p);
            EXPECT_TRUE(std::find(near.begin(), near.end(), e) != near.end()) << "element " << e;
            ++checked;
        }
    }
    EXPECT_GT(checked, 3000);
}

TEST(BlobCells, WalkVisitsTheRaysCellsInOrderWithoutGaps) {
    const std::vector<Metacube> elements = random_elements(200, 3);
    BlobCells cells;
    cells.build(elements);
    std::mt19937_64 rng(4);
    for (int r = 0; r < 200; ++r) {
        const Vec3d origin = random_vector(rng, -6, 6), direction = random_vector(rng, -1, 1);
        double last_exit = 0;
        std::vector<std::uint32_t> seen;
        cells.walk(origin, direction, 0, 100, [&](std::uint32_t cell, double t0, double t1) {
            EXPECT_LE(t0, t1);
            EXPECT_GE(t0, last_exit - 1e-12);  // in increasing t
            last_exit = t1;
            seen.push_back(cell);
            return true;
        });
        // Every cell the segment really crosses is visited (brute force over all cells, interior points).
        for (std::uint32_t c = 0; c < cells.cells().size(); ++c) {
            const BlobCells::Cell& cell = cells.cells()[c];
            double t0 = 0, t1 = 100;
            for (int k = 0; k < 3; ++k) {
                if (direction[k] == 0) continue;
                double a = (cell.lower[k] - origin[k]) / direction[k], b = (cell.upper[k] - origin[k]) / direction[k];
                if (a > b) std::swap(a, b);
                t0 = std::max(t0, a);
                t1 = std::min(t1, b);
            }
            if (t1 - t0 > 1e-9) {
                EXPECT_TRUE(std::find(seen.begin(), seen.end(), c) != seen.end()) << "ray " << r;
            }
        }
    }
}

TEST(BlobCells, RestrictingToTheSurfaceMovesCellsWithoutRegionLastAndKeepsTheirLists) {
    const std::vector<Metacube> elements = random_elements(300, 5);
    BlobCells cells;
    cells.build(elements);
    const std::vector<BlobCells::Cell> before(cells.cells().begin(), cells.cells().end());
    // Every third cell has no region; the others shrink to their lower half along x.
    std::atomic<std::size_t> calls = 0;  // the region is asked for the cells in parallel (ThreadSanitizer found it)
    cells.restrict_to_surface([&](const WorldBounds& box, std::span<const std::uint32_t>) -> std::optional<WorldBounds> {
        std::size_t index = 0;  // which cell: boxes are distinct
        while (before[index].lower != box.lower || before[index].upper != box.upper) ++index;
        ++calls;
        if (index % 3 == 0) return std::nullopt;
        WorldBounds half = box;
        half.upper.x = 0.5 * (box.lower.x + box.upper.x);
        return half;
    });
    EXPECT_EQ(calls.load(), before.size());
    ASSERT_EQ(cells.cells().size(), before.size());
    EXPECT_EQ(cells.surface_cell_count(), before.size() - (before.size() + 2) / 3);
    // Surface cells first, in their old order, then the others; every list kept.
    std::size_t next_surface = 0, next_other = cells.surface_cell_count();
    for (std::size_t old = 0; old < before.size(); ++old) {
        const std::size_t now = old % 3 == 0 ? next_other++ : next_surface++;
        const BlobCells::Cell& cell = cells.cells()[now];
        EXPECT_EQ(cell.first, before[old].first);
        EXPECT_EQ(cell.count, before[old].count);
        if (old % 3 == 0) {
            EXPECT_GT(cell.lower.x, cell.upper.x);  // no box
        } else {
            EXPECT_EQ(cell.upper.x, 0.5 * (before[old].lower.x + before[old].upper.x));
        }
        // Point queries still find the cell's list, also in a cell without region and outside a shrunk box.
        const Vec3d inside_old_box = before[old].lower * 0.2 + before[old].upper * 0.8;
        const auto near = cells.elements_near(inside_old_box);
        EXPECT_EQ(near.data(), cells.elements_of(cell).data()) << "cell " << old;
    }
}

TEST(BlobCells, CoincidentElementsStopTheSplitting) {
    std::vector<Metacube> elements(500, Metacube::metaball({0.5, 0.5, 0.5}, 1.0, 1.0));
    BlobCells cells;
    cells.build(elements);
    ASSERT_EQ(cells.cells().size(), 1u);
    EXPECT_EQ(cells.elements_of(0).size(), 500u);
    EXPECT_TRUE(cells.elements_near({2.5, 0.5, 0.5}).empty());
}

TEST(BlobCells, PointsOutsideTheCellsHaveNoElements) {
    // Two balls share one cell (few elements): its box is the union of their supports, x in [-1, 6].
    const std::vector<Metacube> elements{Metacube::metaball({0, 0, 0}, 1, 1), Metacube::metaball({5, 0, 0}, 1, 1)};
    BlobCells cells;
    cells.build(elements);
    ASSERT_EQ(cells.cells().size(), 1u);
    EXPECT_TRUE(cells.elements_near({0, 3, 0}).empty());
    EXPECT_TRUE(cells.elements_near({-1.5, 0, 0}).empty());
    EXPECT_EQ(cells.elements_near({0.5, 0, 0}).size(), 2u);
}

}  // namespace
}  // namespace isotrace
