// Random rays against random dense blob groups (all five kernels; metaballs alone, and with rotated non-uniform
// metacubes; negative weights, coincident elements), compared with a slow oracle that shares nothing with the cell
// march but the element slices: every element of the group on every piece (no cells, no candidates), each piece's
// field built by polynomial products and solved by Sturm sequences (or sampled densely where a kernel piece is not
// a polynomial). Occlusion queries are checked against the first crossing. 10⁴ rays in the default suite;
// ISOTRACE_BLOB_STRESS_RAYS raises it (the `long` CTest label runs 10⁶).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <random>
#include <string>

#include "geometry/implicit/implicit_test_support.h"
#include "geometry/implicit/metacube_ray_slices.h"
#include "tests/support/sturm_sequence.h"

namespace isotrace {
namespace {

struct OracleCrossing {
    double t;
    bool entering;
};

// An element whose support the line crosses, with its slices along the line.
struct Sliced {
    const Metacube* element;
    MetacubeRaySlices slices;
};

// Where the field along the line may change form: every slice's ends and where dist² reaches a kernel piece's start
// (sampled finely and bisected, so as not to share the march's quadratic solver), sorted.
std::vector<double> oracle_breaks(const std::vector<Sliced>& sliced, const FieldFunction& kernel, double t_min,
                                  double t_max) {
    std::vector<double> breaks{t_min, t_max};
    for (const Sliced& s : sliced) {
        const FieldPieces pieces = kernel.pieces(s.element->radius());
        for (const RegionPiece& piece : s.slices.pieces()) {
            breaks.push_back(piece.t_begin);
            breaks.push_back(piece.t_end);
            for (int k = 1; k < pieces.count; ++k) {
                const QuadraticAbout q = s.slices.distance_squared(piece, piece.t_begin);
                const double level = pieces.pieces[std::size_t(k)].r2_begin;
                const int steps = 256;
                for (int i = 0; i < steps; ++i) {
                    double lo = piece.t_begin + (piece.t_end - piece.t_begin) * i / steps;
                    double hi = piece.t_begin + (piece.t_end - piece.t_begin) * (i + 1) / steps;
                    if ((q(lo) < level) == (q(hi) < level)) continue;
                    for (int j = 0; j < 200 && hi - lo > 1e-15 * (1 + std::abs(hi)); ++j) {
                        const double mid = 0.5 * (lo + hi);
                        ((q(mid) < level) == (q(lo) < level) ? lo : hi) = mid;
                    }
                    breaks.push_back(0.5 * (lo + hi));
                }
            }
        }
    }
    std::sort(breaks.begin(), breaks.end());
    return breaks;
}

// The field on the piece [s0, s1] as a polynomial in u = t − s0, by products of Polynomial values; std::nullopt where
// a kernel piece counting there is no polynomial.
std::optional<Polynomial> oracle_piece_polynomial(const BlobGroup& group, const std::vector<Sliced>& sliced,
                                                  double s0, double s1) {
    const double middle = 0.5 * (s0 + s1);
    Polynomial sum{-group.threshold()};
    for (const Sliced& s : sliced) {
        if (middle < s.slices.t_in() || middle > s.slices.t_out()) continue;
        const RegionPiece* piece = nullptr;
        for (const RegionPiece& p : s.slices.pieces())
            if (middle >= p.t_begin && middle <= p.t_end) piece = &p;
        if (!piece) continue;
        const QuadraticAbout q = s.slices.distance_squared(*piece, s0);
        const Polynomial r2{q.c0, q.c1, q.c2};
        const double r2_middle = std::max(0.0, q(middle));
        // Kept in a variable: span() of the temporary would dangle (AddressSanitizer: stack-use-after-scope).
        const FieldPieces kernel_pieces = group.kernel().pieces(s.element->radius());
        for (const FieldPiece& kp : kernel_pieces.span()) {
            if (!(r2_middle >= kp.r2_begin && r2_middle <= kp.r2_end)) continue;
            if (!kp.is_polynomial) return std::nullopt;
            Polynomial term{kp.coefficients[std::size_t(kp.degree)]};
            for (int k = kp.degree - 1; k >= 0; --k) term = term * r2 + Polynomial{kp.coefficients[std::size_t(k)]};
            sum += term * s.element->weight();
            break;
        }
    }
    return sum;
}

// Every sign change of F along o + t·d in (t_min, t_max), by brute force.
std::vector<OracleCrossing> oracle_crossings(const BlobGroup& group, const Vec3d& origin, const Vec3d& direction,
                                             double t_min, double t_max) {
    std::vector<Sliced> sliced;
    for (const Metacube& element : group.elements())
        if (const auto slices = MetacubeRaySlices::slice(element, origin, direction))
            sliced.push_back({&element, *slices});
    const std::vector<double> breaks = oracle_breaks(sliced, group.kernel(), t_min, t_max);
    // The field from every element whose support the line crosses (the others are zero along it).
    const auto total = [&](double t) {
        double sum = -group.threshold();
        for (const Sliced& s : sliced) sum += s.element->field(group.kernel(), origin + direction * t);
        return sum;
    };
    std::vector<OracleCrossing> found;
    const auto add = [&](double t, int before) {
        if (t > t_min && t < t_max) found.push_back({t, before < 0});
    };
    int sign = total(t_min) > 0 ? 1 : -1;
    for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
        const double s0 = std::max(breaks[b], t_min), s1 = std::min(breaks[b + 1], t_max);
        if (!(s1 > s0)) continue;
        if (const std::optional<Polynomial> sum = oracle_piece_polynomial(group, sliced, s0, s1)) {
            for (const PolynomialRoot& root : sturm_roots(*sum, 0, s1 - s0)) {
                if (root.tangent) continue;
                const double before = sum->evaluate(root.t - 1e-9 * (s1 - s0));
                const double after = sum->evaluate(root.t + 1e-9 * (s1 - s0));
                if ((before > 0) == (after > 0)) continue;
                if ((after > 0 ? 1 : -1) == sign) continue;
                add(s0 + root.t, sign);
                sign = -sign;
            }
            continue;
        }
        const int steps = 128;
        double previous_t = s0, previous = total(s0);
        for (int i = 1; i <= steps; ++i) {
            const double t = s0 + (s1 - s0) * i / steps;
            const double value = total(t);
            if ((value > 0) != (previous > 0)) {
                double lo = previous_t, hi = t;
                for (int j = 0; j < 200 && hi - lo > 1e-15 * (1 + std::abs(hi)); ++j) {
                    const double mid = 0.5 * (lo + hi);
                    ((total(mid) > 0) == (previous > 0) ? lo : hi) = mid;
                }
                add(hi, previous > 0 ? 1 : -1);
                sign = value > 0 ? 1 : -1;
            }
            previous_t = t;
            previous = value;
        }
    }
    return found;
}

// A dense random group: `count` elements in a 2 m cube, metaballs and rotated non-uniform metacubes, one in six
// carving, one in ten a copy of an earlier one (coincident). With `metaballs_only` the boxes drawn are dropped
// (the same random numbers are drawn): the group then takes the march compiled for metaballs alone.
BlobGroup dense_group(std::mt19937_64& rng, const std::string& kernel, int count, bool metaballs_only) {
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Metacube> elements;
    for (int i = 0; i < count; ++i) {
        if (i > 0 && u(rng) < 0.1) {
            elements.push_back(elements[std::size_t(u(rng) * double(elements.size()))]);
            continue;
        }
        OrientedBox box;
        box.centre = random_vector(rng, -1, 1);
        if (u(rng) < 0.4) {
            box.axes = random_axes(rng);
            for (int k = 0; k < 3; ++k) box.half_size[k] = u(rng) < 0.2 ? 0 : 0.3 * u(rng);
            if (metaballs_only) {
                box.axes = OrientedBox{}.axes;
                box.half_size = {};
            }
        }
        const double radius = 0.3 + 0.5 * u(rng);
        const double weight = u(rng) < 1.0 / 6 ? -0.6 : 0.7 + 0.6 * u(rng);
        elements.emplace_back(box, radius, weight);
    }
    return BlobGroup(std::move(elements), make_field_function(kernel, 4.0), 0.5);
}

long long stress_rays() {
    const char* value = std::getenv("ISOTRACE_BLOB_STRESS_RAYS");
    return value ? std::atoll(value) : 10000;
}

// ISOTRACE_BLOB_STRESS_FIRST_GROUP=N draws the groups and rays before group N without tracing them, so that a
// failure reported deep in a long run ("group N ray R") reproduces in seconds.
long long first_traced_group() {
    const char* value = std::getenv("ISOTRACE_BLOB_STRESS_FIRST_GROUP");
    return value ? std::atoll(value) : 0;
}

// The first crossing of o + t·d in (0, t_max) and the occlusion query, against the oracle's crossings `expected` (a
// pair of them closer than the tolerance is a graze: finding both or neither is right). Returns whether there is a
// crossing; context() names the ray in failures.
template <class Context>
bool first_crossing_agrees(const BlobGroup& group, const Vec3d& origin, const Vec3d& direction, double t_max,
                           const std::vector<OracleCrossing>& expected, const Context& context, long long& graze_pairs) {
    BlobQueryWork work;
    const auto first = group.first_crossing(origin, direction, 0, t_max, work);
    const double tolerance = 1e-7 * t_max;
    std::size_t first_expected = 0;
    while (!first && first_expected + 1 < expected.size() &&
           expected[first_expected + 1].t - expected[first_expected].t < tolerance) {
        first_expected += 2;
        ++graze_pairs;
    }
    // Occlusion (a cell that starts inside after a ray start outside ends at once): the same answer as the first
    // crossing.
    EXPECT_EQ(occluded_in_any_cell(group, origin, direction, 0, t_max, work), first.has_value())
        << context() << " occlusion";
    if (first_expected >= expected.size()) {
        EXPECT_FALSE(first) << context() << " spurious crossing at " << first->t;
        return false;
    }
    EXPECT_TRUE(first) << context() << " missed the crossing at " << expected[first_expected].t;
    if (!first) return false;
    const bool matches_first = std::abs(first->t - expected[0].t) <= tolerance;
    const bool graze_skipped = expected.size() > 1 && expected[1].t - expected[0].t < tolerance &&
                               expected.size() > 2 && std::abs(first->t - expected[2].t) <= tolerance;
    EXPECT_TRUE(matches_first || graze_skipped) << context() << ": " << first->t << " vs oracle " << expected[0].t;
    EXPECT_EQ(first->entering, matches_first ? expected[0].entering : expected[2].entering) << context();
    return true;
}

// Traces the rays of groups [first_group, rays / 50) (the groups before are drawn, not traced) and compares.
void compare_with_oracle(long long first_group, long long rays) {
    std::mt19937_64 rng(20261124);
    std::uniform_real_distribution<double> u(0, 1);
    long long compared = 0, hits = 0, all_compared = 0, graze_pairs = 0, thin_dips = 0;
    const auto& kernels = field_function_names();
    const long long rays_per_group = 50;
    for (long long group_index = 0; compared < rays; ++group_index) {
        const std::string kernel(kernels[std::size_t(group_index) % kernels.size()]);
        // Odd groups are metaballs alone (the kernels cycle through five, so each kernel gets both kinds).
        const BlobGroup group = dense_group(rng, kernel, 20 + int(u(rng) * 60), group_index % 2 == 1);
        for (long long r = 0; r < rays_per_group && compared < rays; ++r, ++compared) {
            // Half the rays from outside aimed into the cloud, half from a point inside it.
            const bool from_inside = u(rng) < 0.5;
            const Vec3d origin = from_inside ? random_vector(rng, -1, 1) : normalize(random_vector(rng, -1, 1)) * 4.0;
            const Vec3d target = random_vector(rng, -1, 1);
            const Vec3d direction = (target - origin) * (0.3 + u(rng));  // not unit length
            const double t_max = 12.0 / length(direction);
            if (group_index < first_group) continue;
            const std::vector<OracleCrossing> expected = oracle_crossings(group, origin, direction, 0, t_max);
            const auto context = [&] {
                return kernel + " group " + std::to_string(group_index) + " ray " + std::to_string(r);
            };
            const double tolerance = 1e-7 * t_max;
            // The oracle samples non-polynomial pieces densely and can miss a pair of crossings closer than its
            // step: the march's pair is right when F in its middle has the other sign than just before it.
            const auto total = [&](double t) {
                double sum = -group.threshold();
                for (const Metacube& e : group.elements()) sum += e.field(group.kernel(), origin + direction * t);
                return sum;
            };
            const auto dip_confirmed = [&](double a, double b) {
                return (total(0.5 * (a + b)) > 0) != (total(a - 0.5 * (b - a)) > 0);
            };
            const bool hit = first_crossing_agrees(group, origin, direction, t_max, expected, context, graze_pairs);
            if (::testing::Test::HasFailure()) return;
            if (!hit) continue;
            ++hits;
            // Every crossing, as CSG asks for them, on one ray in five.
            if (r % 5 != 0) continue;
            std::vector<FieldCrossing> all;
            BlobQueryWork work;
            group.crossings(origin, direction, 0, t_max, all, work);
            std::size_t i = 0, j = 0;
            while (i < all.size() || j < expected.size()) {
                if (i < all.size() && j < expected.size() && std::abs(all[i].t - expected[j].t) <= tolerance) {
                    EXPECT_EQ(all[i].entering, expected[j].entering) << context();
                    ++i, ++j;
                } else if (j + 1 < expected.size() && expected[j + 1].t - expected[j].t < tolerance) {
                    j += 2;  // a graze the march did not split
                    ++graze_pairs;
                } else if (i + 1 < all.size() && all[i + 1].t - all[i].t < tolerance) {
                    i += 2;  // a graze the oracle did not split
                    ++graze_pairs;
                } else if (i + 1 < all.size() && (j >= expected.size() || all[i + 1].t < expected[j].t) &&
                           dip_confirmed(all[i].t, all[i + 1].t)) {
                    i += 2;  // a dip narrower than the oracle's sampling, confirmed by the field itself
                    ++thin_dips;
                } else {
                    FAIL() << context() << " crossing lists differ at march " << i << " / oracle " << j << ": "
                           << (i < all.size() ? all[i].t : -1) << " vs " << (j < expected.size() ? expected[j].t : -1);
                }
            }
            ++all_compared;
        }
    }
    EXPECT_GT(hits, (rays - first_group * rays_per_group) / 4);
    ::testing::Test::RecordProperty("rays", std::to_string(compared));
    ::testing::Test::RecordProperty("graze_pairs", std::to_string(graze_pairs));
    std::printf("blob stress: %lld rays, %lld hits, %lld all-crossing lists, %lld graze pairs, %lld thin dips\n",
                compared, hits, all_compared, graze_pairs, thin_dips);
}

TEST(BlobStress, RandomRaysAgreeWithTheBruteForceOracle) { compare_with_oracle(first_traced_group(), stress_rays()); }

// Rays that start on the surface, a few float ulps off it as secondary rays do (SurfaceHit::spawn_origin), leaving
// it or heading in: F is within a hair of T at their start, where the march of metaballs settles the first piece by
// the elements' chords (metaball_march.h) rather than by its polynomial. Their first crossing and occlusion must
// still agree with the oracle.
TEST(BlobStress, RaysFromTheSurfaceAgreeWithTheBruteForceOracle) {
    std::mt19937_64 rng(20261129);
    std::uniform_real_distribution<double> u(0, 1);
    const auto& kernels = field_function_names();
    long long rays = 0, hits = 0, graze_pairs = 0;
    for (int group_index = 0; group_index < 60; ++group_index) {
        const std::string kernel(kernels[std::size_t(group_index) % kernels.size()]);
        const BlobGroup group = dense_group(rng, kernel, 20 + int(u(rng) * 60), group_index % 2 == 1);
        for (int point_index = 0; point_index < 10; ++point_index) {
            const Vec3d from = normalize(random_vector(rng, -1, 1)) * 4.0;
            const Vec3d towards = random_vector(rng, -1, 1) - from;
            BlobQueryWork work;
            const auto surface = group.first_crossing(from, towards, 0, 12.0 / length(towards), work);
            if (!surface) continue;
            const Vec3d point = from + towards * surface->t;
            const Vec3d normal = group.normal(point);
            for (int k = 0; k < 4; ++k) {
                // Leaving (k even) or heading in, from the side it heads for.
                const double side = k % 2 == 0 ? 1 : -1;
                Vec3d direction = normalize(random_vector(rng, -1, 1));
                if (dot(direction, normal) * side < 0) direction = -direction;
                const Vec3d origin = point + normal * (side * 4e-7 * (1 + length(point)));
                const double t_max = 12.0;
                const auto context = [&] {
                    return kernel + " group " + std::to_string(group_index) + " point " +
                           std::to_string(point_index) + " ray " + std::to_string(k);
                };
                hits += first_crossing_agrees(group, origin, direction, t_max,
                                              oracle_crossings(group, origin, direction, 0, t_max), context,
                                              graze_pairs);
                if (::testing::Test::HasFailure()) return;
                ++rays;
            }
        }
    }
    EXPECT_GT(rays, 1000);
    EXPECT_GT(hits, rays / 4);
    std::printf("blob stress from the surface: %lld rays, %lld hits, %lld graze pairs\n", rays, hits, graze_pairs);
}

// The groups where the 10⁶-ray run once found the march wrong (or the oracle blind), replayed in the default
// suite: a flat skeleton's dist² rounding below 0 (Nishimura, 196), bisection landing on the last of three roots
// (Blinn, 270 and 530), F = 0 exactly at a search midpoint (Nishimura, 1301), a dip narrower than the oracle's
// sampling (Nishimura, 13031).
TEST(BlobStress, GroupsThatOnceFailed) {
    for (const long long group : {196, 270, 530, 1301, 13031}) compare_with_oracle(group, (group + 1) * 50);
}

}  // namespace
}  // namespace isotrace
