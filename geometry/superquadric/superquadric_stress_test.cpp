// Random rays against random superquadrics over the whole supported exponent range — boxes and thin stars included
// (ε from 0.02 to 4, drawn evenly in log scale so both extremes come up often) — with random subsets of taper,
// twist and bend and a random placement, compared with a brute-force float64 oracle: the field sampled densely
// along the part of the ray inside the object's bounds, each sign change bisected. The first crossing must be the
// oracle's first crossing; a hit the oracle did not see must be a real sign change of the field (a feature thinner
// than the oracle's samples); no answer is allowed only where the oracle's crossings pair up closer than the
// search's resolution (a grazing contact). 10⁴ rays in the default suite; ISOTRACE_SUPERQUADRIC_STRESS_RAYS raises
// it (the `long` CTest label runs 10⁶).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "geometry/superquadric/superquadric.h"
#include "geometry/superquadric/superquadric_test_support.h"

namespace isotrace {
namespace {

using superquadric_test::make_superquadric;
using superquadric_test::random_deformations;
using superquadric_test::random_ray;
using superquadric_test::RandomRay;

std::size_t stress_rays() {
    const char* text = std::getenv("ISOTRACE_SUPERQUADRIC_STRESS_RAYS");
    return text ? std::size_t(std::strtoull(text, nullptr, 10)) : 10000;
}

// A superquadric with exponents drawn log-uniformly from the supported range, each of the three deformations kept
// with probability 1/2 (a kept stage that is not valid over the object is left out), and a random rotation and
// translation.
Superquadric random_superquadric(std::mt19937& random, Vec3d& radii) {
    std::uniform_real_distribution<double> size(0.3, 1.5), log_exponent(std::log(Superellipsoid::kMinExponent),
                                                                         std::log(Superellipsoid::kMaxExponent));
    std::uniform_real_distribution<double> unit(-1, 1);
    radii = {size(random), size(random), size(random)};
    const double north_south = std::exp(log_exponent(random)), east_west = std::exp(log_exponent(random));
    const std::vector<Deformation> all = random_deformations(random, radii);
    const unsigned kept = unsigned(random()) & 7u;
    const Vec3d axis{unit(random), unit(random), unit(random) + 1e-3};
    const Transform placement =
        Transform::translate({unit(random), unit(random), unit(random)}) * Transform::rotate(axis, 180 * unit(random));
    const Superellipsoid shape{radii, north_south, east_west};
    DeformationChain chain(shape);
    for (std::size_t k = 0; k < all.size(); ++k) {
        if (!(kept & (1u << k))) continue;
        try {
            chain.append(all[k]);
        } catch (const std::invalid_argument&) {
        }
    }
    return Superquadric(shape, std::move(chain), placement);
}

// A translation within ±1 along each axis after a turn of up to 180° about a random axis.
Transform random_placement(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(-1, 1);
    const Vec3d offset{unit(random), unit(random), unit(random)};
    const Vec3d axis{unit(random), unit(random), unit(random) + 1e-3};
    return Transform::translate(offset) * Transform::rotate(axis, 180 * unit(random));
}

// The part [t0, t1] of origin + t·direction, t in [t_min, t_max], inside `box`; empty when t0 > t1.
std::pair<double, double> clip_to_box(const IntervalBox& box, const Vec3d& origin, const Vec3d& direction,
                                      double t_min, double t_max) {
    double t0 = t_min, t1 = t_max;
    for (int k = 0; k < 3; ++k) {
        if (direction[k] == 0) {
            if (origin[k] < box[k].lo || origin[k] > box[k].hi) return {1, 0};
            continue;
        }
        double a = (box[k].lo - origin[k]) / direction[k], b = (box[k].hi - origin[k]) / direction[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    return {t0, t1};
}

struct OracleAnswer {
    std::vector<double> crossings;  // increasing, each bisected to a few ulps
};

// Samples the field at `samples` evenly spaced points of [t0, t1] and bisects every sign change.
OracleAnswer oracle(const Superquadric& s, const Vec3d& origin, const Vec3d& direction, double t0, double t1,
                    int samples) {
    OracleAnswer answer;
    const auto inside = [&](double t) { return s.field(origin + direction * t) < 0; };
    double previous = t0;
    bool previous_inside = inside(t0);
    for (int i = 1; i <= samples; ++i) {
        const double t = t0 + (t1 - t0) * i / samples;
        const bool now_inside = inside(t);
        if (now_inside != previous_inside) {
            double lo = previous, hi = t;
            for (int j = 0; j < 200 && hi - lo > 4e-16 * std::abs(hi); ++j) {
                const double mid = 0.5 * (lo + hi);
                (inside(mid) == previous_inside ? lo : hi) = mid;
            }
            answer.crossings.push_back(0.5 * (lo + hi));
        }
        previous = t;
        previous_inside = now_inside;
    }
    return answer;
}

// What first_crossing answers, checked against the oracle.
struct FirstCrossingTally {
    std::size_t hits = 0, thin_hits = 0, grazing_misses = 0;
};

// s.first_crossing along origin + t·direction, t ∈ [0, t_max], against the oracle with `samples` samples: empty where
// they agree, else what is wrong.
std::string check_first_crossing(const Superquadric& s, const Vec3d& origin, const Vec3d& direction, double t_max,
                                 int samples, SuperquadricWork& work, FirstCrossingTally& tally) {
    const IntervalBox bounds = s.bounds();
    const double size = std::max({bounds.x.width(), bounds.y.width(), bounds.z.width()});
    // Two crossings closer than this may be taken for a grazing contact (the search's rule).
    const double grazing = 4 * Superquadric::kRelativeResolution * size;
    const std::optional<double> t = s.first_crossing(origin, direction, 0, t_max, work);
    const auto [t0, t1] = clip_to_box(bounds, origin, direction, 0, t_max);
    const OracleAnswer expected = t0 < t1 ? oracle(s, origin, direction, t0, t1, samples) : OracleAnswer{};
    const double scale = length(direction);
    const auto real_crossing = [&](double at) {
        const double step = 1e-9 * size / scale + 1e-12 * at;
        return (s.field(origin + direction * (at - step)) < 0) != (s.field(origin + direction * (at + step)) < 0);
    };
    if (t) {
        ++tally.hits;
        if (!real_crossing(*t)) return "a hit where the field does not change sign";
        if (!expected.crossings.empty() && expected.crossings[0] < *t - grazing / scale) {
            // An earlier crossing was skipped, unless it pairs up with a second one within the resolution.
            if (!(expected.crossings.size() > 1 && expected.crossings[1] - expected.crossings[0] < grazing / scale))
                return "missed the crossing at " + std::to_string(expected.crossings[0]);
        } else if (expected.crossings.empty() || expected.crossings[0] > *t + grazing / scale) {
            ++tally.thin_hits;  // a real crossing between the oracle's samples
        } else if (std::abs(*t - expected.crossings[0]) > 1e-9 * std::max(1.0, std::abs(*t))) {
            return "hit at " + std::to_string(*t) + " but the crossing is at " + std::to_string(expected.crossings[0]);
        }
    } else if (!expected.crossings.empty()) {
        if (!(expected.crossings.size() > 1 && expected.crossings[1] - expected.crossings[0] < grazing / scale))
            return "no hit, but the field changes sign at " + std::to_string(expected.crossings[0]);
        ++tally.grazing_misses;
    }
    return {};
}

// Hands visit(s, origin, direction, r, done) random rays (in the placed shape's space, every fifth from inside)
// against random superquadrics, twenty each, until `rays` were handed over or twenty visits returned false.
template <class Visit>
void visit_random_rays(std::mt19937& random, std::size_t rays, Visit&& visit) {
    constexpr int kRaysPerShape = 20;
    std::size_t failures = 0;
    for (std::size_t done = 0; done < rays && failures < 20;) {
        Vec3d radii;
        const Superquadric s = random_superquadric(random, radii);
        for (int r = 0; r < kRaysPerShape && done < rays; ++r, ++done) {
            const RandomRay local = random_ray(random, radii, r % 5 == 0);
            const Vec3d origin = s.placement().point(local.origin), direction = s.placement().vector(local.direction);
            if (!visit(s, origin, direction, r, done)) ++failures;
        }
    }
}

TEST(SuperquadricStress, RandomRaysFindTheOraclesFirstCrossing) {
    const std::size_t rays = stress_rays();
    constexpr int kSamples = 4000;
    constexpr double kTMax = 40;
    std::mt19937 random(55);
    FirstCrossingTally tally;
    visit_random_rays(random, rays, [&](const Superquadric& s, const Vec3d& origin, const Vec3d& direction, int,
                                        std::size_t done) {
        SuperquadricWork work;
        const std::string problem = check_first_crossing(s, origin, direction, kTMax, kSamples, work, tally);
        if (problem.empty()) return true;
        ADD_FAILURE() << problem << " (ε1 " << s.shape().north_south() << ", ε2 " << s.shape().east_west() << ", "
                      << s.deformation().size() << " deformations, ray " << done << ")";
        return false;
    });
    std::printf("%zu rays: %zu hits (%zu between the oracle's samples), %zu grazing contacts left out\n", rays,
                tally.hits, tally.thin_hits, tally.grazing_misses);
    EXPECT_GT(tally.hits, rays / 5);
}

// Occlusion queries give first_crossing's answer (which the test above holds to the oracle) on random rays from
// outside and inside random shapes, with ranges that end before, inside and beyond them: the shortcuts that settle
// a query by one value inside the solid (where a ray comes nearest a convex shape's centre, at the middle of a
// deformed shape's stretch) or by the shell's cells alone may not block a ray that first_crossing lets through.
TEST(SuperquadricStress, OcclusionQueriesGiveTheFirstCrossingsAnswer) {
    const std::size_t rays = stress_rays();
    std::mt19937 random(61);
    std::uniform_real_distribution<double> range(0, 12);
    std::size_t blocked = 0;
    visit_random_rays(random, rays, [&](const Superquadric& s, const Vec3d& origin, const Vec3d& direction, int r,
                                        std::size_t done) {
        const float t_max = r % 3 ? float(range(random)) : std::numeric_limits<float>::infinity();
        SuperquadricWork work;
        const std::optional<double> t = s.first_crossing(origin, direction, 0, t_max, work);
        const bool expected = t && *t > 0 && float(*t) < t_max;
        blocked += expected;
        if (s.blocks(origin, direction, 0, t_max, work) == expected) return true;
        ADD_FAILURE() << "blocks() says " << !expected << " (ε1 " << s.shape().north_south() << ", ε2 "
                      << s.shape().east_west() << ", " << s.deformation().size() << " deformations, ray " << done
                      << ")";
        return false;
    });
    std::printf("%zu rays: %zu blocked\n", rays, blocked);
    EXPECT_GT(blocked, rays / 5);
}

// Rays leaving tapered (and twisted round) convex shapes, which one point value settles where the level set through
// their start is convex (DeformationChain::convex_levels): from just outside the surface (pushed out along a line from
// the centre by 10⁻⁷ to 10⁻¹ of the way), in every direction, the ones moving outward and the ones turning back in,
// against the oracle. Tapers of every rate a shape takes, also beyond the levels that are known convex.
TEST(SuperquadricStress, RaysLeavingTaperedOrTwistedConvexShapesFindTheOraclesFirstCrossing) {
    const std::size_t rays = stress_rays();
    constexpr int kRaysPerShape = 20, kSamples = 4000;
    constexpr double kTMax = 40;
    std::mt19937 random(59);
    std::uniform_real_distribution<double> unit(-1, 1), size(0.3, 1.5), rate(-0.95, 2.0),
        log_round(std::log(Superellipsoid::kMinExponent), std::log(2.0)), log_push(std::log(1e-7), std::log(1e-1));
    FirstCrossingTally tally;
    std::size_t failures = 0, settled_at_once = 0;
    for (std::size_t done = 0; done < rays && failures < 20;) {
        // A third of the shapes with round cross-sections, twisted before or after the taper (or only twisted).
        const bool round = random() % 3 == 0;
        Vec3d radii{size(random), size(random), size(random)};
        if (round) radii.y = radii.x;
        const double north_south = std::exp(log_round(random)), east_west = round ? 1 : std::exp(log_round(random));
        const Superellipsoid shape{radii, north_south, east_west};
        DeformationChain chain(shape);
        const auto maybe_twist = [&] {
            if (round && random() % 2) chain.append(Twist(1.5 * unit(random) / radii.z, radii.z));
        };
        // One rate for both axes half the time: only such tapers keep levels convex.
        const double rate_x = rate(random), rate_y = random() % 2 ? rate_x : rate(random);
        try {
            maybe_twist();
            if (!round || random() % 4 != 0) chain.append(Taper(rate_x, rate_y, radii.z));
            maybe_twist();
        } catch (const std::invalid_argument&) {
            continue;  // a scale that does not stay positive over the object
        }
        const Transform placement = random_placement(random);
        const Superquadric s(shape, std::move(chain), placement);
        for (int r = 0; r < kRaysPerShape && done < rays; ++r, ++done) {
            // The surface along a line from the centre (inside: the taper keeps the middle's cross-section), found
            // by bisection, then a point a little beyond it on the line.
            const Vec3d out = normalize(Vec3d{unit(random), unit(random), unit(random)});
            const auto inside = [&](double t) { return s.field(placement.point(out * t)) < 0; };
            double lo = 0, hi = 4 * std::max({radii.x, radii.y, radii.z});
            for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) (inside(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
            const Vec3d origin = placement.point(out * (hi * (1 + std::exp(log_push(random)))));
            const Vec3d direction = placement.vector(Vec3d{unit(random), unit(random), unit(random)});
            SuperquadricWork work;
            const std::string problem = check_first_crossing(s, origin, direction, kTMax, kSamples, work, tally);
            settled_at_once += work.point_values == 1 && work.search.interval_bounds == 0;
            if (!problem.empty()) {
                ++failures;
                ADD_FAILURE() << problem << " (ε1 " << shape.north_south() << ", ε2 " << shape.east_west()
                              << ", levels known convex up to " << s.deformation().convex_levels() << ", ray " << done
                              << ", rates " << rate_x << " and " << rate_y << ")";
            }
        }
    }
    std::printf("%zu rays: %zu hits, %zu settled by their start's value and slope\n", rays, tally.hits,
                settled_at_once);
    EXPECT_GT(tally.hits, rays / 10);
    EXPECT_GT(settled_at_once, rays / 10);
}

// Undeformed stars, whose crossings come from tangent cutting planes (both exponents ≥ 2, concave_crossings.h) or
// from the bounds of a difference of convex functions (one exponent on each side of 2, difference_of_convex.h) on
// each piece between the coordinate planes: every crossing, not only the first, against the oracle, with rays
// aimed at the coordinate planes and axes, where the pieces meet at the stars' cusps.
TEST(SuperquadricStress, UndeformedStarsGiveEveryCrossingTheOracleSees) {
    const std::size_t rays = stress_rays() / 4;
    constexpr int kRaysPerShape = 20, kSamples = 4000;
    constexpr double kTMax = 40;
    std::mt19937 random(57);
    std::uniform_real_distribution<double> unit(-1, 1), size(0.3, 1.5), star(2, Superellipsoid::kMaxExponent),
        log_round(std::log(Superellipsoid::kMinExponent), std::log(2.0));
    std::size_t crossings_found = 0, grazing_pairs = 0, failures = 0;
    for (std::size_t done = 0; done < rays && failures < 20;) {
        const Vec3d radii{size(random), size(random), size(random)};
        const bool mixed = done % 40 >= 20, round_north_south = random() % 2;
        const double first = star(random), second = mixed ? std::exp(log_round(random)) : star(random);
        const Superellipsoid shape{radii, round_north_south ? second : first, round_north_south ? first : second};
        const Transform placement = random_placement(random);
        const Superquadric s(shape, DeformationChain(shape), placement);
        const IntervalBox bounds = s.bounds();
        const double grazing = 4 * Superquadric::kRelativeResolution *
                               std::max({bounds.x.width(), bounds.y.width(), bounds.z.width()});
        for (int r = 0; r < kRaysPerShape && done < rays; ++r, ++done) {
            RandomRay local = random_ray(random, radii, r % 5 == 0);
            if (r % 3 == 1) {  // through a coordinate plane's trace or an axis of the star
                Vec3d target = local.origin + local.direction * 0.5;
                target[r % 3] = 0;
                if (r % 2) target[(r + 1) % 3] = 0;
                local.direction = target - local.origin;
            }
            const Vec3d origin = placement.point(local.origin), direction = placement.vector(local.direction);
            SuperquadricWork work;
            std::vector<Crossing> found;
            s.crossings(origin, direction, 0, kTMax, found, work);
            const auto [t0, t1] = clip_to_box(bounds, origin, direction, 0, kTMax);
            const std::vector<double> expected =
                t0 < t1 ? oracle(s, origin, direction, t0, t1, kSamples).crossings : std::vector<double>{};
            const double scale = length(direction);
            std::string problem;
            std::size_t next = 0;  // the next reported crossing to match
            for (std::size_t i = 0; i < expected.size() && problem.empty(); ++i) {
                const bool paired_closely = (i + 1 < expected.size() && expected[i + 1] - expected[i] < grazing / scale) ||
                                            (i > 0 && expected[i] - expected[i - 1] < grazing / scale);
                while (next < found.size() && found[next].t < expected[i] - 1e-9 * std::max(1.0, expected[i])) {
                    // A crossing the oracle's samples stepped over must still be a real sign change.
                    const double at = found[next].t, step = 1e-9 * (t1 - t0) + 1e-12 * at;
                    if ((s.field(origin + direction * (at - step)) < 0) == (s.field(origin + direction * (at + step)) < 0))
                        problem = "a crossing at " + std::to_string(at) + " where the field keeps its sign";
                    ++next;
                }
                if (next < found.size() && std::abs(found[next].t - expected[i]) <= 1e-9 * std::max(1.0, expected[i])) {
                    const bool entering = s.field(origin + direction * (expected[i] + 1e-9 * (t1 - t0))) < 0;
                    if (found[next].entering != entering) problem = "a crossing reported with the wrong direction";
                    ++next;
                    ++crossings_found;
                } else if (paired_closely) {
                    ++grazing_pairs;
                } else if (problem.empty()) {
                    problem = "the field changes sign at " + std::to_string(expected[i]) + ", not reported";
                }
            }
            if (!problem.empty()) {
                ++failures;
                ADD_FAILURE() << problem << " (ε1 " << shape.north_south() << ", ε2 " << shape.east_west() << ", ray "
                              << done << ")";
            }
        }
    }
    std::printf("%zu rays: %zu crossings found, %zu grazing pairs left out\n", rays, crossings_found, grazing_pairs);
    EXPECT_GT(crossings_found, rays / 2);
}

}  // namespace
}  // namespace isotrace
