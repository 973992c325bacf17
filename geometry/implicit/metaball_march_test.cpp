// The metaball march against known crossings and against the general march it stands in for: on every surface cell
// of random metaball groups, the same crossings (to rounding: its sums run in another order) and the same normals.
#include "geometry/implicit/metaball_march.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "geometry/implicit/field_march.h"
#include "geometry/implicit/implicit_test_support.h"
#include "geometry/implicit/kim_sextic.h"
#include "geometry/implicit/murakami_quartic.h"
#include "geometry/implicit/nishimura_quadratic.h"
#include "geometry/implicit/wyvill_sextic.h"

namespace isotrace {
namespace {

struct Found {
    std::vector<FieldCrossing> crossings;
    std::vector<Vec3d> gradients;  // at each crossing's point
    bool done = false;             // the march took the query
};

// Collects every crossing of a stretch, and the gradient the march gives at each.
struct CollectAll {
    static constexpr bool kPlaceNeeded = true;
    const MarchStretch& stretch;
    Found& out;

    template <class March>
    bool found(const FieldCrossing& c, const March& march) {
        out.crossings.push_back(c);
        out.gradients.push_back(march.gradient_at(stretch.origin + stretch.direction * c.t));
        return false;
    }
    bool crossed_before() { return false; }
};

template <class March>
Found march_all(March& march, std::span<const std::uint32_t> listed, const MarchStretch& stretch) {
    Found found;
    BlobQueryWork work;
    CollectAll query{stretch, found};
    if constexpr (std::is_same_v<decltype(march.run(listed, stretch, work, query)), bool>) {
        found.done = march.run(listed, stretch, work, query);
    } else {  // the general march takes every query
        march.run(listed, stretch, work, query);
        found.done = true;
    }
    return found;
}

// The first crossing's t, placed or not.
template <bool kPlace>
struct FirstT {
    static constexpr bool kPlaceNeeded = kPlace;
    std::optional<double> t;

    template <class March>
    bool found(const FieldCrossing& c, const March&) {
        t = c.t;
        return true;
    }
    bool crossed_before() { return false; }
};

std::vector<Metacube> random_metaballs(std::mt19937_64& rng, int count, double spread) {
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Metacube> elements;
    for (int i = 0; i < count; ++i) {
        OrientedBox box;
        box.centre = random_vector(rng, -spread, spread);
        const double weight = u(rng) < 0.15 ? -0.6 : 0.7 + 0.6 * u(rng);
        elements.emplace_back(box, 0.3 + 0.4 * u(rng), weight);
    }
    return elements;
}

// A random group of 300 metaballs with what a march reads (bounding spheres, cells), and 400 random rays through it:
// visit(group, ray, cell, stretch) for each ray's stretch through each cell it meets.
struct MarchedGroup {
    explicit MarchedGroup(std::vector<Metacube> group) : elements(std::move(group)) {
        for (const Metacube& e : elements) {
            spheres.push_back(BoundingSphere::of(e));
            centre_bound = std::max(centre_bound, length(e.centre()) + 1e-6);
        }
        cells.build(elements);
    }
    std::vector<Metacube> elements;
    std::vector<BoundingSphere> spheres;
    double centre_bound = 0;
    BlobCells cells;
};

template <class Visit>
void for_each_stretch(std::uint64_t seed, Visit&& visit) {
    std::mt19937_64 rng(seed);
    const MarchedGroup group(random_metaballs(rng, 300, 2.0));
    for (int ray = 0; ray < 400; ++ray) {
        const Vec3d origin = normalize(random_vector(rng, -1, 1)) * 5.0;
        const Vec3d direction = (random_vector(rng, -1.5, 1.5) - origin) * 0.7;
        group.cells.walk(origin, direction, 0, 1e3, [&](std::uint32_t cell, double t0, double t1) {
            visit(group, ray, cell, MarchStretch{origin, direction, t0, t1, 0, 1e3});
            return true;
        });
    }
}

// Every surface cell of the group's cells, each ray's stretch through it marched by both marches.
template <class Kernel>
void expect_same_as_general_march(const Kernel& kernel, std::uint64_t seed) {
    const double threshold = 0.5;
    int compared = 0, crossings = 0, declined = 0, identical_gradients = 0;
    for_each_stretch(seed, [&](const MarchedGroup& group, int ray, std::uint32_t cell, const MarchStretch& stretch) {
        MetaballMarch<Kernel> fast(kernel, threshold, group.elements, group.spheres, group.centre_bound);
        FieldMarch<Kernel, true> general(kernel, threshold, group.elements, group.spheres, group.centre_bound);
        const Found a = march_all(fast, group.cells.elements_of(cell), stretch);
        if (!a.done) {
            ++declined;
            return;
        }
        const Found b = march_all(general, group.cells.elements_of(cell), stretch);
        ++compared;
        EXPECT_EQ(a.crossings.size(), b.crossings.size()) << "ray " << ray << " cell " << cell;
        for (std::size_t i = 0; i < std::min(a.crossings.size(), b.crossings.size()); ++i) {
            EXPECT_NEAR(a.crossings[i].t, b.crossings[i].t, 1e-9 * (1 + std::abs(b.crossings[i].t)));
            EXPECT_EQ(a.crossings[i].entering, b.crossings[i].entering);
            EXPECT_LT(length(a.gradients[i] - b.gradients[i]), 1e-7 * (1 + length(b.gradients[i])));
            // The sum BlobGroup::gradient makes over the cell's list, in ascending order, at the same point:
            // the same bits unless an element's support begins a rounding away from the crossing.
            const Vec3d point = stretch.origin + stretch.direction * a.crossings[i].t;
            Vec3d expected(0, 0, 0);
            for (const std::uint32_t j : group.cells.elements_of(cell))
                expected += group.elements[j].field_gradient(kernel, point);
            identical_gradients += a.gradients[i] == expected;
            ++crossings;
        }
    });
    EXPECT_GT(compared, 1000);
    EXPECT_GT(crossings, 200);
    EXPECT_LT(declined, compared / 10);
    EXPECT_GE(identical_gradients, crossings - crossings / 100);
}

TEST(MetaballMarch, FindsTheSameCrossingsAndNormalsAsTheGeneralMarch) {
    expect_same_as_general_march(KimSextic{}, 1);
    expect_same_as_general_march(WyvillSextic{}, 2);
    expect_same_as_general_march(MurakamiQuartic{}, 3);
}

// Occlusion asks only whether a crossing lies on the stretch: the march without kPlaceNeeded gives the answer of the
// one that places crossings, on every surface cell of random groups, and reports its crossing inside the stretch.
template <class Kernel>
void expect_same_occlusion(const Kernel& kernel, std::uint64_t seed) {
    int occluded = 0, unsolved = 0;
    for_each_stretch(seed, [&](const MarchedGroup& group, int ray, std::uint32_t cell, const MarchStretch& stretch) {
        const auto answer = [&]<bool kPlaceNeeded>(BlobQueryWork& work) {
            MetaballMarch<Kernel> march(kernel, 0.5, group.elements, group.spheres, group.centre_bound);
            FirstT<kPlaceNeeded> query;
            march.run(group.cells.elements_of(cell), stretch, work, query);
            return query.t;
        };
        BlobQueryWork placing, asking;
        const std::optional<double> placed = answer.template operator()<true>(placing);
        const std::optional<double> any = answer.template operator()<false>(asking);
        EXPECT_EQ(placed.has_value(), any.has_value()) << "ray " << ray << " cell " << cell;
        if (any) {
            EXPECT_GE(*any, stretch.t_begin);
            EXPECT_LE(*any, stretch.t_end);
            ++occluded;
            unsolved += asking.polynomial_solves < placing.polynomial_solves;
        }
    });
    EXPECT_GT(occluded, 200);
    EXPECT_GT(unsolved, occluded / 4);  // most crossings are proven without a solve
}

TEST(MetaballMarch, AnswersOcclusionAsTheMarchThatPlacesCrossings) {
    expect_same_occlusion(KimSextic{}, 4);
    expect_same_occlusion(WyvillSextic{}, 5);
    expect_same_occlusion(MurakamiQuartic{}, 6);
}

TEST(MetaballMarch, LoneMetaballIsCrossedAtItsIsoRadius) {
    const KimSextic kernel;
    const double radius = 2, weight = 1.5, threshold = 0.5;
    OrientedBox box;
    box.centre = {1, -2, 3};
    const std::vector<Metacube> elements{Metacube(box, radius, weight)};
    const std::vector<BoundingSphere> spheres{BoundingSphere::of(elements[0])};
    const std::uint32_t listed[] = {0};
    const double iso = *kernel.iso_radius(radius, weight, threshold);
    // Along +x through the centre, not unit length: in at centre.x − iso, out at centre.x + iso.
    const Vec3d origin(-10, -2, 3), direction(2, 0, 0);
    MetaballMarch<KimSextic> march(kernel, threshold, elements, spheres, 4);
    const Found found = march_all(march, listed, {origin, direction, 0, 20, 0, 20});
    ASSERT_TRUE(found.done);
    ASSERT_EQ(found.crossings.size(), 2u);
    EXPECT_NEAR(found.crossings[0].t, (11 - iso) / 2, 1e-12);
    EXPECT_TRUE(found.crossings[0].entering);
    EXPECT_NEAR(found.crossings[1].t, (11 + iso) / 2, 1e-12);
    EXPECT_FALSE(found.crossings[1].entering);
    // ∇(F + T) points into the ball: +x on the near side.
    EXPECT_GT(found.gradients[0].x, 0);
    EXPECT_NEAR(found.gradients[0].y, 0, 1e-15);
}

TEST(MetaballMarch, LeavesMoreThanItsLanesToTheGeneralMarch) {
    const KimSextic kernel;
    std::vector<Metacube> elements;
    std::vector<BoundingSphere> spheres;
    std::vector<std::uint32_t> listed;
    for (std::uint32_t i = 0; i <= MetaballMarch<KimSextic>::kMaxLanes; ++i) {
        OrientedBox box;
        box.centre = {0.01 * i, 0, 0};
        elements.emplace_back(box, 1.0, 0.1);
        spheres.push_back(BoundingSphere::of(elements.back()));
        listed.push_back(i);
    }
    MetaballMarch<KimSextic> march(kernel, 0.5, elements, spheres, 1);
    const MarchStretch through{{-5, 0, 0}, {1, 0, 0}, 0, 10, 0, 10};
    EXPECT_FALSE(march_all(march, listed, through).done);
    // One fewer fits, and the sum of sixteen nearly coincident balls of weight 0.1 reaches the threshold.
    listed.pop_back();
    const Found found = march_all(march, listed, through);
    EXPECT_TRUE(found.done);
    EXPECT_EQ(found.crossings.size(), 2u);
}

TEST(MetaballMarch, AppliesToMetaballsOfAOnePiecePolynomialKernel) {
    const auto applies = [](std::vector<Metacube> elements, const char* kernel) {
        return BlobGroup(std::move(elements), make_field_function(kernel, 4.0), 0.5).view().metaball_march;
    };
    std::vector<Metacube> balls{Metacube(OrientedBox{}, 1, 1)};
    EXPECT_TRUE(applies(balls, "kim"));
    EXPECT_TRUE(applies(balls, "wyvill"));
    EXPECT_TRUE(applies(balls, "murakami"));
    EXPECT_FALSE(applies(balls, "nishimura"));  // two pieces
    EXPECT_FALSE(applies(balls, "blinn"));      // not a polynomial
    OrientedBox cube;
    cube.half_size = {0.5, 0.5, 0.5};
    balls.emplace_back(cube, 1, 1);
    EXPECT_FALSE(applies(balls, "kim"));
}

// The Bernstein test of a piece composed in its own u allows 4ε·(terms + 20) of the magnitude of every value the
// composition formed: a control value within that of zero has no trusted sign (the piece goes to the general root
// search), one beyond it keeps its sign.
TEST(MetaballMarch, APieceComposedInUDistrustsValuesWithinItsRoundingAllowance) {
    const Polynomial rising{-1e-15, 1};  // control values −10⁻¹⁵ and 1 − 10⁻¹⁵
    const int terms = 3;
    const double allowance_per_magnitude = 4 * std::numeric_limits<double>::epsilon() * (terms + 20);
    EXPECT_EQ(march_piece::bernstein_signs_on_piece(rising, terms, 2e-15 / allowance_per_magnitude).variations,
              kUntrustedSign);
    const BernsteinSigns trusted =
        march_piece::bernstein_signs_on_piece(rising, terms, 0.5e-15 / allowance_per_magnitude);
    EXPECT_EQ(trusted.variations, 1);
    EXPECT_NEAR(trusted.polygon_crossing, 1e-15, 1e-30);
}

}  // namespace
}  // namespace isotrace
