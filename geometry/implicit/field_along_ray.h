#pragma once
// The summed field F(t) = Σ wᵢ·fᵢ(dist²ᵢ(o + t·d)) − T of a set of blob elements along one ray, and where it
// changes sign. The ray is cut at every breakpoint of every element (support ends, metacube region planes,
// kernel piece boundaries); on each piece every element's field is a polynomial in t (or, for non-polynomial
// kernels, a function with a known Lipschitz bound). Pieces whose interval bound on F excludes 0 are skipped
// without solving; the others are solved with the monotone root finder or searched with the Lipschitz bound.
//
// F > 0 is inside the surface. The caller supplies every element whose field is non-zero somewhere in the
// examined range [a, b]; the crossings are then exact for that range.
#include <cstdint>
#include <vector>

#include "geometry/implicit/field_function.h"
#include "geometry/implicit/metacube.h"
#include "geometry/implicit/metacube_ray_slices.h"

namespace isotrace {

// Work done by ray queries, for the statistics.
struct BlobQueryWork {
    std::uint64_t pieces = 0;  // ray pieces examined
    std::uint64_t skipped_pieces = 0;  // of which the interval bound proved free of crossings
    std::uint64_t polynomial_solves = 0;
    std::uint64_t lipschitz_searches = 0;
    std::uint64_t root_iterations = 0;  // Newton/bisection steps of the polynomial solves and Lipschitz searches
    std::uint64_t roots = 0;            // crossings reported

    BlobQueryWork& operator+=(const BlobQueryWork& other);
};

// A sign change of F: entering the surface (F becomes > 0) or leaving it, found on the piece of `element`.
struct FieldCrossing {
    double t = 0;
    bool entering = false;
    std::uint32_t element = 0;  // an element whose support contains the crossing (the hit's primitive)
};

class FieldAlongRay {
public:
    // Starts a query of the field of `kernel` elements with threshold T over [a, b], forgetting the previous one
    // (one object serves query after query, keeping its buffers).
    void reset(const FieldFunction& kernel, double threshold, double a, double b);
    // Adds an element whose support the ray meets; ignored unless its support overlaps (a, b). `slices` must
    // stay valid until the next reset.
    void add(std::uint32_t index, const Metacube& element, const MetacubeRaySlices& slices);
    bool empty() const { return active_.empty(); }

    // Where the examined stretch ended: b, or the last crossing reported when `max_count` stopped the search.
    // F has sign `sign_before_end` just before `t_end` and no crossing in (start, t_end) other than those
    // reported.
    // `complete` is false when a sign change outside (t_min, t_max) went unreported, so that the stretch is not
    // free of crossings after all.
    struct Stop {
        double t_end = 0;
        int sign_before_end = 0;
        bool complete = true;
    };
    // Appends, in increasing t, up to `max_count` crossings with t in (t_min, t_max) ∩ [a, b].
    // `sign_before_a` is F's sign just before a (+1 inside, −1 outside), so that a step at a (a hard cube's face)
    // is a crossing; 0 means unknown, and then F is evaluated just before a when a > t_min.
    Stop crossings(double t_min, double t_max, int sign_before_a, std::size_t max_count,
                   std::vector<FieldCrossing>& out, BlobQueryWork& work);

    // F at t (from the added elements).
    double value(double t) const;

private:
    struct Active {
        std::uint32_t index;
        const Metacube* element;
        const MetacubeRaySlices* slices;
        FieldPieces kernel_pieces;
        std::size_t cursor = 0;                // region piece the sweep has reached
        const RegionPiece* current = nullptr;  // the region piece on the ray piece being examined
    };

    const FieldFunction* kernel_ = nullptr;
    double threshold_ = 1;
    double a_ = 0, b_ = 0;
    std::vector<Active> active_;
    std::vector<double> breaks_;
};

}  // namespace isotrace
