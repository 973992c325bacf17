#pragma once
// The summed field F(t) = Σ wᵢ·fᵢ(dist²ᵢ(o + t·d)) − T of a blob group along one stretch [t_begin, t_end] of a
// ray (one cell's part of it, blob_cells.h), marched once from front to back:
//   1. the cell's elements whose bounding sphere the stretch may meet bound F from above at their nearest approach
//      (below T the stretch holds no crossing, and many queries end here); otherwise those the stretch meets
//      become candidates, ordered by entry;
//   2. a candidate joins the march when the march reaches its entry: it is cut into pieces on which its field is
//      one closed form (metacube region pieces, metacube_ray_slices.h; kernel pieces such as Nishimura's r = R/3);
//   3. between consecutive events (an entry, an exit, a piece boundary) F is a polynomial in t when every kernel
//      piece is one;
//   4. each piece is first bounded by every counting element's own range (most pieces end here, without any
//      polynomial), then by the Bernstein coefficients of the summed polynomial (all of one sign beyond rounding:
//      no crossing), and only the others are solved (march_piece.h), or searched with a Lipschitz bound
//      when a non-polynomial kernel piece (Blinn, Nishimura's outer piece) is present. An element's polynomial is
//      composed only when a piece first needs it and kept until its piece changes; the sum is formed afresh from
//      those terms whenever it is needed, so no rounding drift accumulates along the march;
//   5. crossings are reported in increasing t; the query decides whether the march goes on (a nearest-hit or
//      shadow query stops at the first, CSG takes them all).
// Steps 3–5 are the piece march (piece_march.h); this class is its Elements for a list of joined elements.
// F > 0 is inside. Every crossing is a sign change of F: a tangent touch (a double root) is not one.
//
// Groups of metaballs alone whose kernel is one polynomial piece take MetaballMarch (metaball_march.h) instead, which
// leaves queries with more near elements than its lanes to this one.
//
// Kernel is the concrete FieldFunction class, so that its calls inline (no virtual call per evaluation).
// kMetaballsOnly is set for groups of metaballs alone (no metacube, no hard cube: the benchmark clouds and most
// scenes): the metacube slices and the hard cubes' steps are then compiled out, with the same arithmetic for
// everything else, so the results are the same bits as the general march's.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "geometry/implicit/field_function.h"
#include "geometry/implicit/march_piece.h"
#include "geometry/implicit/metacube.h"
#include "geometry/implicit/metacube_ray_slices.h"
#include "geometry/implicit/piece_march.h"
#include "geometry/implicit/sphere_prefilter.h"
#include "geometry/polynomial/bernstein.h"
#include "geometry/polynomial/quadratic_roots.h"
#include "renderer/core/inline_vector.h"
#include "renderer/math/branch_free.h"

namespace isotrace {

namespace field_march_detail {

// Depth of the Lipschitz search: 2⁻⁹⁰ of a piece is far below double resolution, so the stack never limits it.
constexpr int kMaxSearchDepth = 90;
constexpr double kUnset = std::numeric_limits<double>::infinity();

using march_piece::sign_of;

// An element's term of the sum on one piece: a kernel piece (degree ≤ 3 in x = r²/R²) composed with x(s), a
// quadratic in s, so of degree ≤ 6. A plain array: the sum adds whole arrays, and no Polynomial is built per term.
struct Term {
    static constexpr std::size_t kSize = 2 * (std::tuple_size_v<decltype(FieldPiece::coefficients)> - 1) + 1;
    std::array<double, kSize> coefficients;  // [0, degree] are set
    int degree;
};

// w·Σₖ βₖ·xᵏ as a polynomial in s, for a kernel piece Σₖ βₖ·xᵏ of degree kDegree and a quadratic x(s) (Horner on
// coefficients), written to `term`, where it is kept. Each step multiplies by x(s), every new coefficient from the
// old ones (cᵢ ← cᵢ₋₂·c2 + cᵢ₋₁·c1 + cᵢ·c0). The loops unroll completely, so the coefficients stay in registers and
// are stored once: kept in memory between steps, or returned by value, they were re-read in 16-byte loads of what
// had just been stored 8 bytes at a time, each waiting for those stores (a failed store forwarding,
// docs/decisions.md "Hot data is written the way it is read"). The same operations as plain Horner, so the same
// bits.
template <int kDegree>
void compose_with_quadratic(const FieldPiece& piece, double weight, const QuadraticAbout& q, Term& term) {
    std::array<double, Term::kSize> c{};
    c[0] = weight * piece.coefficients[std::size_t(kDegree)];
#pragma GCC unroll 4
    for (int k = kDegree - 1; k >= 0; --k) {
        const std::size_t degree = std::size_t(2 * (kDegree - 1 - k));  // of c before this step
        const std::array<double, Term::kSize> old = c;
        c[0] = old[0] * q.c0 + weight * piece.coefficients[std::size_t(k)];
#pragma GCC unroll 8
        for (std::size_t i = 1; i <= degree + 2; ++i) {
            if (i == 1) c[1] = degree == 0 ? old[0] * q.c1 : old[0] * q.c1 + old[1] * q.c0;
            else if (i == degree + 2) c[i] = old[degree] * q.c2;
            else if (i == degree + 1) c[i] = old[degree - 1] * q.c2 + old[degree] * q.c1;
            else c[i] = old[i - 2] * q.c2 + old[i - 1] * q.c1 + old[i] * q.c0;
        }
    }
    for (std::size_t i = 0; i <= std::size_t(2 * kDegree); ++i) term.coefficients[i] = c[i];
    term.degree = 2 * kDegree;
}

inline void compose_with_quadratic(const FieldPiece& piece, double weight, const QuadraticAbout& q, Term& term) {
    static_assert(std::tuple_size_v<decltype(FieldPiece::coefficients)> == 4, "kernel pieces of degree <= 3");
    switch (piece.degree) {
        case 0: return compose_with_quadratic<0>(piece, weight, q, term);
        case 1: return compose_with_quadratic<1>(piece, weight, q, term);
        case 2: return compose_with_quadratic<2>(piece, weight, q, term);
        default: return compose_with_quadratic<3>(piece, weight, q, term);
    }
}

struct Range {
    double low, high;
};
// Where q is least when it opens upwards (c2 > 0); −∞ otherwise, which quadratic_range clamps to the start.
inline double quadratic_vertex(const QuadraticAbout& q) {
    return q.c2 > 0 ? q.t_ref - q.c1 / (2 * q.c2) : -std::numeric_limits<double>::infinity();
}
// Smallest and largest value of the quadratic q (a squared distance, never below 0) on [s0, s1]. `vertex` is
// quadratic_vertex(q), kept by the caller: q changes once per piece, its range is asked per event. Branch free:
// it is asked for every joined element at every event, and which end is nearer is data.
inline Range quadratic_range(const QuadraticAbout& q, double vertex, double s0, double s1) {
    const double at_s0 = q(s0), at_s1 = q(s1);
    const double nearest = min_branch_free(max_branch_free(vertex, s0), s1);
    return {max_branch_free(min_branch_free(min_branch_free(at_s0, at_s1), q(nearest)), 0.0),
            max_branch_free(at_s0, at_s1)};
}

}  // namespace field_march_detail

template <class Kernel, bool kMetaballsOnly>
class FieldMarch {
public:
    // centre_bound ≥ the largest |centre| of the spheres.
    FieldMarch(const Kernel& kernel, double threshold, std::span<const Metacube> elements,
               std::span<const BoundingSphere> spheres, double centre_bound)
        : kernel_(kernel), threshold_(threshold), elements_(elements), spheres_(spheres),
          centre_bound_(centre_bound), unit_pieces_(kernel.unit_pieces()) {}

    // Marches `stretch` over the field of the `listed` elements (every element whose support may reach the stretch
    // must be among them) for `query` (blob_ray.cpp): each crossing in increasing t goes to query.found(crossing,
    // march), `march` being this march as it stands there (for gradient_at), which returns true to stop; when the
    // stretch starts inside (F > T beyond rounding) after t_min, query.crossed_before() may end the march. `work`
    // collects the statistics.
    template <class Query>
    void run(std::span<const std::uint32_t> listed, const MarchStretch& stretch, BlobQueryWork& work, Query& query);

    // The piece march's Elements (piece_march.h).
    static constexpr bool kAllPolynomial = false;  // Blinn's and Nishimura's outer pieces are searched
    double threshold() const { return threshold_; }
    // Joins the candidates that enter by t; F just after t, a hard cube's step at t included.
    double start(double t) {
        join_until(t);
        return value(t) + hard_cube_step_before(t);
    }
    // Σ |wᵢ| over the counting elements: F + T cannot exceed it (f ≤ 1), so it scales the rounding of value().
    double counting_weights(double) const {
        double sum = 0;
        for (const Active& a : joined_)
            if (a.kernel_piece) sum += std::abs(a.weight);
        return sum;
    }
    template <class March>
    bool settles_stretch(double, double, int, March&) const {
        return false;
    }
    // The next entry of a candidate or end of a joined element's piece (all lie after the current piece's start),
    // at most t_end; the last counting element becomes the witness.
    double next_event(double t0, double t_end);
    template <class March>
    PieceBound bound_piece(double t0, double t1, int previous_sign, March& march) const;
    PieceTest test_piece(double t0, double t1);
    template <class March>
    bool search_piece(double t0, double t1, int& previous_sign, March& march);
    // Events at t1: pieces that end there move on (exits leave the sum), then newcomers join.
    void advance(double t1) {
        for (Active& a : joined_)
            if (a.next_event <= t1) enter_piece(a, t1);
        join_until(t1);
        drop_finished();
    }
    // A hard cube's exit face within rounding of the stretch's end t_end: its step down lies just after t_end, in no
    // piece of this stretch. A lone hard cube's cell is the cube, so its exit is always there and no later cell
    // would report it (CSG then saw every such cube entered and never left). Reports the crossing at t_end when the
    // step changes F's sign.
    template <class March>
    void at_end(double t_end, int previous_sign, March& march) const;
    std::uint32_t witness() const { return witness_; }

    // ∇(F + T) at a point of the crossing just reported, summed over the elements that count on its piece: every
    // element whose support contains the point does (its entry is an event at or before the piece), and the others
    // (hard cubes too) add 0, so this is the sum BlobGroup::gradient makes over a cell's list, and in the same order
    // (ascending element index), hence the same bits; a hit's normal then needs no second search of the cell's
    // list. A point a rounding away from the crossing (a hit's t kept as a float) can miss an element whose support
    // begins between them, whose term there is within rounding of 0.
    Vec3d gradient_at(const Vec3d& point) const;

private:
    // An element whose bounding sphere the stretch meets, waiting for the march to reach its entry.
    struct Candidate {
        double t_enter, t_exit;  // through its bounding sphere (exactly its support for a metaball)
        std::uint32_t index;
    };
    // An element the march has reached. Before its support it does not count; from there its pieces follow each
    // other until the support ends. A metaball has one piece, its support's chord, and carries no slices: a
    // metacube's slices (~300 bytes) are kept aside in box_slices_, so that the list of joined elements, read at
    // every event, stays small (blob groups are mostly metaballs).
    struct Active {
        Active(std::uint32_t index, const Metacube& element, double t_in, double t_out, int box_slices)
            : inverse_radius2(is_hard_cube(element) ? 0 : 1 / (element.radius() * element.radius())),
              weight(element.weight()), t_in(t_in), t_out(t_out), index(index), box_slices(box_slices),
              hard_cube(is_hard_cube(element)) {}
        // First what every loop over the joined elements reads (the next event, the ranges), in one cache line.
        const FieldPiece* kernel_piece = nullptr;  // nullptr: not counting on the current piece
        double next_event = 0;                     // where its current piece ends (kUnset: never again)
        QuadraticAbout q;                          // dist² on the current piece, in s = t − t_ref_
        double q_vertex = 0;                       // quadratic_vertex(q)
        double inverse_radius2;  // 1/R², for x = r²/R² (0 for a hard cube); divisions cost more than the rest
        double weight;           // the element's
        double t_in, t_out;      // its support along the line
        std::uint32_t index;
        int box_slices;          // its slices in box_slices_, or −1 for a metaball (one piece, [t_in, t_out])
        int region = -1;         // current piece of its slices, −1 before the support (metacubes only)
        bool hard_cube;          // the element's
        // Its term of the sum on the current piece (polynomial pieces), once composed. Optional, so that joining
        // zeroes no polynomial (a rep stos per element).
        std::optional<field_march_detail::Term> contribution;
    };

    // The element kinds, constant for a group of metaballs alone (a metaball is never a hard cube).
    static bool is_hard_cube(const Metacube& element) { return !kMetaballsOnly && element.is_hard_cube(); }
    static bool is_hard_cube(const Active& a) { return !kMetaballsOnly && a.hard_cube; }
    static bool is_metaball(const Metacube& element) { return kMetaballsOnly || element.is_metaball(); }
    static double half_diagonal(const Metacube& element) { return kMetaballsOnly ? 0 : element.half_diagonal(); }
    // A hard cube joined this march (F may step).
    bool hard_cube_joined() const { return !kMetaballsOnly && hard_cube_joined_; }

    // Keeps in near_ the listed elements whose support's bounding sphere the stretch may meet; returns an upper
    // bound of Σ wᵢ·fᵢ on the stretch from each one's nearest approach (f is non-increasing in r², negative
    // weights only lower F). No square root or division per element for a metaball: many queries end at this
    // bound, and the chords are found only for the others (order_candidates).
    double gather(std::span<const std::uint32_t> listed, const MarchStretch& stretch);
    // Lists the elements of near_ whose bounding sphere the stretch meets, by entry. The chord is the centre's
    // projection on the line ± the half chord, from the distance to the line (no cancellation, as in Haines et al.'s
    // ray–sphere test) and the 1/|d|² gather found: a square root and no division per element, divisions being the
    // dearest operations here; the roots of the quadratic agree to a few ulps, and an end off by ulps moves where
    // an element is summed by as little, where its field is within rounding of 0 (every kernel vanishes at the edge
    // of its support, all but Blinn's with a zero slope too).
    void order_candidates(const MarchStretch& stretch);
    // Joins every candidate whose entry is ≤ t, each brought to its piece at t.
    void join_until(double t);
    // Brings element `a` to the piece that starts at t (it counts from there on), updating the sum.
    void enter_piece(Active& a, double t);
    // Drops the elements whose support the march has left, once they are half the list. Until then they stay, inert
    // (no piece, no event: every loop skips them); dropping at once would move half a kilobyte per element behind
    // each one that left. The order is kept.
    void drop_finished();
    // Σ of the counting elements' polynomial terms − T (composing the terms not yet composed), and in
    // sum_magnitude_ the Σ of their coefficients' magnitudes (for the rounding bounds).
    const Polynomial& polynomial_sum();
    // F at t, summed directly from the counting elements (no polynomial needed).
    double value(double t) const;
    // Bounds on [t0, t1] of the counting elements' sum Σ wᵢ·fᵢ (of only those on non-polynomial pieces if asked)
    // from each element's own range: f is monotone in r², so its extremes are at the ends of the element's r²
    // range. A few operations per element, no polynomial formed.
    field_march_detail::Range elements_range(double t0, double t1, bool non_polynomial_only) const;
    // Only the upper bound of elements_range(t0, t1, false), one kernel evaluation per element: where the march is
    // outside (F ≤ T) and no hard cube's step can lift F, only F < T needs proving, and the lower bound is a good
    // part of the range's work.
    double elements_upper_bound(double t0, double t1) const;
    double hard_cube_step_before(double t) const;
    // A bound of |dF/dt| on the piece [t0, t1]: the polynomial part's derivative hull, plus per non-polynomial
    // element |w|·max|f'|·max|q'| (f is convex non-increasing in r², so max|f'| is at the smallest r²).
    double lipschitz_bound(double t0, double t1);
    // The kernel on x = r²/R², zero beyond the support (rounding can put a support end a hair past x = 1). Without a
    // branch: in elements_range which side of 1 an element's range ends on is data (evaluated at min(x, 1), masked).
    double unit_value(double x) const { return zero_unless_less(kernel_.unit_value(min_branch_free(x, 1.0)), x, 1.0); }
    double unit_derivative(double x) const { return x < 1 ? kernel_.unit_derivative(x) : 0; }

    const Kernel& kernel_;
    double threshold_;
    std::span<const Metacube> elements_;
    std::span<const BoundingSphere> spheres_;  // per element
    double centre_bound_;
    std::span<const FieldPiece> unit_pieces_;
    double t_ref_ = 0;  // the sum is a polynomial in s = t − t_ref_

    InlineVector<std::uint32_t, 64> near_;    // the elements gather kept
    InlineVector<double, 64> near_middle_;    // per kept element: its centre's projection on the line (t)
    InlineVector<Candidate, 64> candidates_;  // by entry
    std::size_t next_candidate_ = 0;
    InlineVector<Active, 24> joined_;
    InlineVector<MetacubeRaySlices, 4> box_slices_;  // of the joined metacubes and hard cubes
    BlobQueryWork* work_ = nullptr;                   // where its statistics go
    Vec3d origin_, direction_;                        // the marched line
    double inverse_length2_ = 0;                      // 1/|direction|²
    bool sum_valid_ = false;                                        // sum_ matches the counting elements
    // Σ contributions − T, in s; built in place when asked for (a copy of it re-read, as 16-byte loads, what its
    // constructor had just stored 8 bytes at a time).
    std::optional<Polynomial> sum_;
    std::array<double, kMaxPolynomialDegree + 1> sum_magnitude_;  // Σ |coefficients| of its terms and T
    int sum_terms_ = 0;
    int non_polynomial_ = 0;  // counting elements whose current kernel piece is not a polynomial
    bool hard_cube_joined_ = false;  // a hard cube joined this march (F may step)
    std::uint32_t witness_ = 0;      // an element counting on the current piece
    Polynomial on_piece_;            // F on the current piece in u ∈ [0,1], for the polynomial pieces left open
};

template <class Kernel, bool kMetaballsOnly>
double FieldMarch<Kernel, kMetaballsOnly>::gather(std::span<const std::uint32_t> listed, const MarchStretch& stretch) {
    const Vec3d& o = stretch.origin;
    const Vec3d& d = stretch.direction;
    // Most listed elements are far from the stretch: their compact bounding spheres reject them, several at a time
    // and without a branch per element (walking each group's passing lanes instead mispredicts its exits).
    near_.clear();
    append_near(listed, spheres_, near_stretch_test(stretch, centre_bound_), near_);
    inverse_length2_ = 1 / dot(d, d);
    const double rounding = nearest_approach_rounding(stretch, centre_bound_);
    double upper = 0;  // Σ wᵢ·max fᵢ on the stretch over elements of positive weight
    std::size_t kept = 0;
    near_middle_.clear();
    for (const std::uint32_t index : near_) {
        // The element's support lies in the sphere of radius R + |half-size| about its centre. The stretch's point
        // nearest the centre (its projection on the line, clamped) decides whether the stretch may meet that
        // sphere, and bounds the field: the skeleton box is no nearer than that distance less its half-diagonal.
        const Metacube& element = elements_[index];
        const double half_diagonal = FieldMarch::half_diagonal(element);
        const double reach = element.radius() + half_diagonal;
        const double t_middle = dot(element.centre() - o, d) * inverse_length2_;
        const Vec3d to_centre = o + d * std::clamp(t_middle, stretch.t_begin, stretch.t_end) - element.centre();
        double gap2 = dot(to_centre, to_centre);  // a metaball's own distance: no square root
        const double keep = reach * (1 + 1e-9) + rounding;
        if (gap2 > keep * keep) continue;
        near_[kept++] = index;
        near_middle_.push_back(t_middle);
        if (element.weight() <= 0) continue;
        double f_max = 1;  // a hard cube's step
        if (!is_hard_cube(element)) {
            if (half_diagonal > 0) {
                const double gap = std::max(0.0, std::sqrt(gap2) - half_diagonal);
                gap2 = gap * gap;
            }
            f_max = unit_value(gap2 / (element.radius() * element.radius()));
        }
        upper += element.weight() * f_max;
    }
    near_.truncate(kept);
    return upper;
}

template <class Kernel, bool kMetaballsOnly>
void FieldMarch<Kernel, kMetaballsOnly>::order_candidates(const MarchStretch& stretch) {
    candidates_.clear();
    next_candidate_ = 0;
    const Vec3d& o = stretch.origin;
    const Vec3d& d = stretch.direction;
    for (std::size_t i = 0; i < near_.size(); ++i) {
        // Entry and exit of the line through the support's bounding sphere (exact for metaballs, whose support is
        // the sphere).
        const std::uint32_t index = near_[i];
        const Metacube& element = elements_[index];
        const double reach = element.radius() + half_diagonal(element);
        const double t_middle = near_middle_[i];
        const Vec3d to_line = o + d * t_middle - element.centre();
        const double half_chord2 = (reach * reach - dot(to_line, to_line)) * inverse_length2_;
        if (!(half_chord2 >= 0)) continue;
        const double half_chord = std::sqrt(half_chord2);
        const double t_enter = t_middle - half_chord, t_exit = t_middle + half_chord;
        if (!(t_exit > stretch.t_begin && t_enter < stretch.t_end)) continue;
        candidates_.push_back({t_enter, t_exit, index});
    }
    std::sort(candidates_.begin(), candidates_.end(), [](const Candidate& x, const Candidate& y) {
        return x.t_enter < y.t_enter || (x.t_enter == y.t_enter && x.index < y.index);
    });
}

template <class Kernel, bool kMetaballsOnly>
void FieldMarch<Kernel, kMetaballsOnly>::join_until(double t) {
    while (next_candidate_ < candidates_.size() && candidates_[next_candidate_].t_enter <= t) {
        const Candidate& candidate = candidates_[next_candidate_++];
        const Metacube& element = elements_[candidate.index];
        const auto join = [&](double t_in, double t_out, int box_slices) {
            ++work_->joined;
            hard_cube_joined_ = hard_cube_joined_ || is_hard_cube(element);
            enter_piece(joined_.emplace_back(candidate.index, element, t_in, t_out, box_slices), t);
        };
        if (is_metaball(element)) {
            // Its support is its bounding sphere: the chord order_candidates found.
            if (candidate.t_exit > t) join(candidate.t_enter, candidate.t_exit, -1);
            continue;
        }
        const auto slices = MetacubeRaySlices::slice(element, origin_, direction_);
        if (!slices || !(slices->t_out() > t)) continue;
        box_slices_.push_back(*slices);
        join(slices->t_in(), slices->t_out(), int(box_slices_.size() - 1));
    }
}

template <class Kernel, bool kMetaballsOnly>
void FieldMarch<Kernel, kMetaballsOnly>::drop_finished() {
    std::size_t finished = 0;  // counted without a branch per element (std::count_if's branch mispredicts)
    for (const Active& a : joined_) finished += a.next_event == field_march_detail::kUnset ? 1 : 0;
    if (2 * finished < joined_.size()) return;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < joined_.size(); ++i) {
        if (joined_[i].next_event == field_march_detail::kUnset) continue;
        if (kept != i) joined_[kept] = joined_[i];
        ++kept;
    }
    joined_.truncate(kept);
}

template <class Kernel, bool kMetaballsOnly>
const Polynomial& FieldMarch<Kernel, kMetaballsOnly>::polynomial_sum() {
    if (sum_valid_) return *sum_;
    std::array<double, field_march_detail::Term::kSize> sum{};
    sum[0] = -threshold_;
    int degree = 0;
    sum_magnitude_ = {};
    sum_magnitude_[0] = threshold_;
    sum_terms_ = 1;
    for (Active& a : joined_) {
        if (!a.kernel_piece || !a.kernel_piece->is_polynomial) continue;
        if (!a.contribution) {
            if (is_hard_cube(a)) {
                a.contribution = field_march_detail::Term{{a.weight}, 0};
            } else {
                // The unit piece is a polynomial in x = r²/R²: compose it with the quadratic x(s) = q(s)/R².
                const QuadraticAbout x{a.q.t_ref, a.q.c0 * a.inverse_radius2, a.q.c1 * a.inverse_radius2,
                                       a.q.c2 * a.inverse_radius2};
                field_march_detail::compose_with_quadratic(*a.kernel_piece, a.weight, x, a.contribution.emplace());
            }
        }
        const field_march_detail::Term& term = *a.contribution;
        for (int i = 0; i <= term.degree; ++i) {
            sum[std::size_t(i)] += term.coefficients[std::size_t(i)];
            sum_magnitude_[std::size_t(i)] += std::abs(term.coefficients[std::size_t(i)]);
        }
        degree = std::max(degree, term.degree);
        ++sum_terms_;
    }
    sum_.emplace(std::span<const double>(sum.data(), std::size_t(degree) + 1));
    sum_valid_ = true;
    return *sum_;
}

template <class Kernel, bool kMetaballsOnly>
void FieldMarch<Kernel, kMetaballsOnly>::enter_piece(Active& a, double t) {
    const Metacube& element = elements_[a.index];
    // Leave the previous piece.
    if (a.kernel_piece) {
        if (a.kernel_piece->is_polynomial) {
            sum_valid_ = false;
        } else {
            --non_polynomial_;
        }
        a.kernel_piece = nullptr;
    }
    a.contribution.reset();
    if (t >= a.t_out) {
        a.next_event = field_march_detail::kUnset;
        return;
    }
    if (t < a.t_in) {  // not yet inside its support
        a.region = -1;
        a.next_event = a.t_in;
        return;
    }
    if (kMetaballsOnly || a.box_slices < 0) {
        a.next_event = a.t_out;
        a.q = MetacubeRaySlices::metaball_distance_squared(origin_, direction_, element.centre(), t_ref_);
        a.q_vertex = field_march_detail::quadratic_vertex(a.q);
    } else {
        const MetacubeRaySlices& slices = box_slices_[std::size_t(a.box_slices)];
        const auto pieces = slices.pieces();
        if (a.region < 0) a.region = 0;
        while (a.region + 1 < int(pieces.size()) && pieces[std::size_t(a.region)].t_end <= t) ++a.region;
        const RegionPiece& region = pieces[std::size_t(a.region)];
        a.next_event = region.t_end;
        a.q = slices.distance_squared(region, t_ref_);
        a.q_vertex = field_march_detail::quadratic_vertex(a.q);
        if (is_hard_cube(element)) {
            // A hard cube counts w inside its box (the region piece with U = 0) and nothing elsewhere.
            static constexpr FieldPiece kConstant{0, 0, true, 0, {1, 0, 0, 0}};
            if (region.region == std::array<int, 3>{0, 0, 0}) {
                a.kernel_piece = &kConstant;
                sum_valid_ = false;
            }
            return;
        }
    }
    const double radius = element.radius();
    // Kernel piece boundaries (levels of r²) split the region piece further.
    const double radius2 = radius * radius;
    for (std::size_t k = 1; k < unit_pieces_.size(); ++k) {
        const double level = unit_pieces_[k].r2_begin * radius2;
        const QuadraticRoots roots = quadratic_roots(a.q.c2, a.q.c1, a.q.c0 - level);
        for (int r = 0; r < roots.count; ++r) {
            const double crossing = t_ref_ + roots.roots[r];
            if (crossing > t && crossing < a.next_event) a.next_event = crossing;
        }
    }
    // dist² is a sum of squares, but its quadratic can round below 0 where the line crosses a flat skeleton.
    const double r2_middle = std::max(0.0, a.q(0.5 * (t + a.next_event)));
    for (const FieldPiece& unit : unit_pieces_)
        if (r2_middle >= unit.r2_begin * radius2 && r2_middle <= unit.r2_end * radius2) a.kernel_piece = &unit;
    if (!a.kernel_piece) return;  // beyond the support on this piece (rounding at its ends)
    if (a.kernel_piece->is_polynomial) {
        sum_valid_ = false;
    } else {
        ++non_polynomial_;
    }
}

template <class Kernel, bool kMetaballsOnly>
field_march_detail::Range FieldMarch<Kernel, kMetaballsOnly>::elements_range(double t0, double t1,
                                                                           bool non_polynomial_only) const {
    double low = 0, high = 0;
    for (const Active& a : joined_) {
        if (!a.kernel_piece || (non_polynomial_only && a.kernel_piece->is_polynomial)) continue;
        double f_near = 1, f_far = 1;  // a hard cube counts its weight wherever it counts
        if (!is_hard_cube(a)) {
            const field_march_detail::Range r2 = field_march_detail::quadratic_range(a.q, a.q_vertex, t0, t1);
            f_near = unit_value(r2.low * a.inverse_radius2);
            f_far = unit_value(r2.high * a.inverse_radius2);
        }
        const double w = a.weight;
        low += min_branch_free(w * f_near, w * f_far);
        high += max_branch_free(w * f_near, w * f_far);
    }
    return {low, high};
}

template <class Kernel, bool kMetaballsOnly>
double FieldMarch<Kernel, kMetaballsOnly>::elements_upper_bound(double t0, double t1) const {
    double high = 0;
    for (const Active& a : joined_) {
        if (!a.kernel_piece) continue;
        double f = 1;  // a hard cube counts its weight wherever it counts
        if (!is_hard_cube(a)) {
            // f is non-increasing in r²: largest at the nearest point for a positive weight, at the farthest for a
            // negative one.
            const field_march_detail::Range r2 = field_march_detail::quadratic_range(a.q, a.q_vertex, t0, t1);
            f = unit_value((a.weight > 0 ? r2.low : r2.high) * a.inverse_radius2);
        }
        high += a.weight * f;
    }
    return high;
}

template <class Kernel, bool kMetaballsOnly>
double FieldMarch<Kernel, kMetaballsOnly>::value(double t) const {
    // From the joined elements' own copies of w and 1/R²: no element read, no division.
    double sum = -threshold_;
    for (const Active& a : joined_) {
        if (!a.kernel_piece) continue;
        sum += a.weight * (is_hard_cube(a) ? 1 : unit_value(std::max(0.0, a.q(t)) * a.inverse_radius2));
    }
    return sum;
}

template <class Kernel, bool kMetaballsOnly>
Vec3d FieldMarch<Kernel, kMetaballsOnly>::gradient_at(const Vec3d& point) const {
    InlineVector<std::uint32_t, 24> ascending;  // the elements counting on the crossing's piece (the rest add 0)
    for (const Active& a : joined_)
        if (a.kernel_piece && !is_hard_cube(a)) ascending.push_back(a.index);
    std::sort(ascending.begin(), ascending.end());
    Vec3d sum(0, 0, 0);
    for (const std::uint32_t index : ascending) sum += elements_[index].field_gradient(kernel_, point);
    return sum;
}

// The hard cubes' share of F just before t minus just after it: a hard cube's closed box counts at its faces,
// so entering one is a step up at t itself and leaving one a step down just after it. A face within rounding of t
// counts as at t: a lone hard cube's cell is the cube, so a stretch starts and ends on its faces, and a face found
// a hair before the start (in the cube's frame, the start in world coordinates) would hide the step from every cell.
template <class Kernel, bool kMetaballsOnly>
double FieldMarch<Kernel, kMetaballsOnly>::hard_cube_step_before(double t) const {
    if constexpr (kMetaballsOnly) return 0;
    const double tolerance = same_place_tolerance(t);
    double step = 0;
    for (const Active& a : joined_) {
        if (!is_hard_cube(a)) continue;
        const bool inside_after = a.kernel_piece != nullptr;
        const bool inside_before = a.t_in < t - tolerance && t <= a.t_out + tolerance;
        step += a.weight * ((inside_before ? 1 : 0) - (inside_after ? 1 : 0));
    }
    return step;
}

template <class Kernel, bool kMetaballsOnly>
template <class March>
void FieldMarch<Kernel, kMetaballsOnly>::at_end(double t_end, int previous_sign, March& march) const {
    if (!hard_cube_joined()) return;
    const double tolerance = same_place_tolerance(t_end);
    double step = 0;
    for (const Active& a : joined_)
        if (is_hard_cube(a) && a.kernel_piece && a.t_out <= t_end + tolerance) step += a.weight;
    if (step == 0) return;
    using march_piece::sign_of;
    const double before = value(t_end);
    if (sign_of(before) == previous_sign && sign_of(before - step) != previous_sign)
        march.crossing(t_end, previous_sign);
}

template <class Kernel, bool kMetaballsOnly>
double FieldMarch<Kernel, kMetaballsOnly>::next_event(double, double t_end) {
    double t1 = t_end;
    if (next_candidate_ < candidates_.size()) t1 = std::min(t1, candidates_[next_candidate_].t_enter);
    for (const Active& a : joined_) {
        t1 = std::min(t1, a.next_event);
        if (a.kernel_piece) witness_ = a.index;
    }
    return t1;
}

// First each element's own range: it proves most pieces free of crossings (F far below T along most of a ray) at a
// fraction of the cost of the sums of test_piece. Coming from outside, F is continuous unless a hard cube steps, so
// it cannot be above T on the whole piece: only its upper bound is needed.
template <class Kernel, bool kMetaballsOnly>
template <class March>
PieceBound FieldMarch<Kernel, kMetaballsOnly>::bound_piece(double t0, double t1, int previous_sign, March&) const {
    PieceBound bound;
    if (previous_sign < 0 && !hard_cube_joined()) {
        bound.settled = march_piece::below_threshold(elements_upper_bound(t0, t1), threshold_);
    } else {
        const field_march_detail::Range range = elements_range(t0, t1, false);
        bound.settled = march_piece::one_side_of_threshold(range.low, range.high, threshold_);
        bound.start_sign = march_piece::sign_of(range.low - threshold_);
    }
    return bound;
}

// The Bernstein test of the summed polynomial; with a non-polynomial kernel piece counting, a tighter bound instead:
// the polynomial part (with −T) bounded by its Bernstein hull, the non-polynomial elements by their own ranges.
template <class Kernel, bool kMetaballsOnly>
PieceTest FieldMarch<Kernel, kMetaballsOnly>::test_piece(double t0, double t1) {
    const double s0 = t0 - t_ref_, width = t1 - t0;
    PieceTest test;
    if (non_polynomial_ == 0) {
        test.signs = march_piece::bernstein_variations(polynomial_sum(), sum_magnitude_, sum_terms_, s0, width,
                                                       on_piece_);
        test.start_sign = march_piece::sign_of(on_piece_[0]);
        test.open = test.signs.variations != 0;
        test.polynomial = &on_piece_;
        return test;
    }
    const BernsteinCoefficients hull = to_bernstein(polynomial_sum().compose_linear(s0, width));
    const field_march_detail::Range others = elements_range(t0, t1, true);
    const double low = *std::min_element(hull.values.begin(), hull.values.begin() + hull.degree + 1) + others.low;
    const double high = *std::max_element(hull.values.begin(), hull.values.begin() + hull.degree + 1) + others.high;
    const double hull_slack = 1e-12 * (std::abs(low) + std::abs(high) + threshold_);
    test.open = !(high < -hull_slack || low > hull_slack);
    test.start_sign = march_piece::sign_of(low);
    return test;
}

template <class Kernel, bool kMetaballsOnly>
double FieldMarch<Kernel, kMetaballsOnly>::lipschitz_bound(double t0, double t1) {
    const double s0 = t0 - t_ref_, width = t1 - t0;
    const BernsteinCoefficients slope_hull = to_bernstein(polynomial_sum().compose_linear(s0, width).derivative());
    double lipschitz = 0;
    for (int k = 0; k <= slope_hull.degree; ++k)
        lipschitz = std::max(lipschitz, std::abs(slope_hull.values[std::size_t(k)]));
    lipschitz /= width;
    for (const Active& a : joined_) {
        if (!a.kernel_piece || a.kernel_piece->is_polynomial) continue;
        const Metacube& element = elements_[a.index];
        const double radius2 = element.radius() * element.radius();
        const double slope =
            std::max(std::abs(a.q.c1 + 2 * a.q.c2 * s0), std::abs(a.q.c1 + 2 * a.q.c2 * (s0 + width)));
        lipschitz += std::abs(element.weight()) *
                     std::abs(unit_derivative(field_march_detail::quadratic_range(a.q, a.q_vertex, t0, t1).low /
                                              radius2) /
                              radius2) *
                     slope;
    }
    return lipschitz;
}

// Subdivides nearer halves first until the Lipschitz bound proves a span free of crossings or the span is as small
// as the resolution; a sign change across such a span is a crossing. Bisecting a bracket instead could land on its
// last root of three, so every span is searched the same way.
template <class Kernel, bool kMetaballsOnly>
template <class March>
bool FieldMarch<Kernel, kMetaballsOnly>::search_piece(double t0, double t1, int& previous_sign, March& march) {
    using march_piece::sign_of;
    ++work_->lipschitz_searches;
    const int sign_at_start = sign_of(value(t0 + (t1 - t0) * 1e-12));
    if (sign_at_start != previous_sign && march.crossing(t0, previous_sign)) return true;
    previous_sign = sign_at_start;
    const double lipschitz = lipschitz_bound(t0, t1);
    struct Span {
        double lo, hi, f_lo, f_hi;
    };
    Span stack[field_march_detail::kMaxSearchDepth + 2];
    int top = 0;
    stack[top++] = {t0, t1, value(t0), value(t1)};
    while (top > 0) {
        const Span span = stack[--top];
        // Signs as everywhere in the march: F = 0 exactly counts as outside.
        const bool sign_change = sign_of(span.f_lo) != sign_of(span.f_hi);
        if (!sign_change && std::abs(span.f_lo) + std::abs(span.f_hi) > lipschitz * (span.hi - span.lo)) continue;
        if (span.hi - span.lo < 1e-13 * (1 + std::abs(span.hi)) || top >= field_march_detail::kMaxSearchDepth) {
            // A crossing must leave the sign the march is in (rounding can flip values a hair from a root).
            if (!sign_change || sign_of(span.f_hi) == previous_sign) continue;
            const int before = previous_sign;
            previous_sign = -before;
            if (march.crossing(span.hi, before)) return true;
            continue;
        }
        ++work_->root_iterations;
        const double mid = 0.5 * (span.lo + span.hi);
        const double f_mid = value(mid);
        stack[top++] = {mid, span.hi, f_mid, span.f_hi};
        stack[top++] = {span.lo, mid, span.f_lo, f_mid};
    }
    previous_sign = sign_of(value(t1));
    return false;
}

template <class Kernel, bool kMetaballsOnly>
template <class Query>
void FieldMarch<Kernel, kMetaballsOnly>::run(std::span<const std::uint32_t> listed, const MarchStretch& stretch,
                                             BlobQueryWork& work, Query& query) {
    const double upper = gather(listed, stretch);
    ++work.queries;
    if (stretch_below_threshold(upper, threshold_)) {
        ++work.queries_bounded;
        work.candidates += near_.size();
        return;
    }
    order_candidates(stretch);
    work.candidates += candidates_.size();
    joined_.clear();
    box_slices_.clear();
    work_ = &work;
    origin_ = stretch.origin;
    direction_ = stretch.direction;
    non_polynomial_ = 0;
    hard_cube_joined_ = false;
    t_ref_ = stretch.t_begin;
    sum_valid_ = false;
    witness_ = 0;
    PieceMarch(*this, stretch, work, query).run();
}

}  // namespace isotrace
