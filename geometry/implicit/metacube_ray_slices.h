#pragma once
// One element seen along a ray o + t·dir (dir need not be unit length): the interval where the element's field
// is non-zero, cut where the squared distance to the box changes form, with that squared distance as an exact
// quadratic in t on each piece. With the kernel's polynomial in r² (field_function.h) composed on top, the
// element's field is a polynomial in t on every piece; a blob group sums its elements on the common refinement
// of their pieces.
//
// The cuts are the paper's region boundaries: the ray crossing a face plane pₖ = ±dₖ in local coordinates (the
// paper's CubeTree of 1 body box + 26 region boxes, without building the tree). The support interval is exact:
// the support {dist ≤ R} is convex (a rounded box) and dist² is convex along a line, so it is one interval,
// found by solving dist²(t) = R² on the pieces, not the looser box grown by R.
#include <array>
#include <optional>
#include <span>

#include "geometry/implicit/metacube.h"

namespace isotrace {

// q(t) = c0 + c1·(t − t_ref) + c2·(t − t_ref)²: written about a reference t chosen near where it is used (the
// start of a piece, say), so the coefficients do not cancel when the ray starts far from the element.
struct QuadraticAbout {
    double t_ref = 0;
    double c0 = 0, c1 = 0, c2 = 0;

    double operator()(double t) const {
        const double s = t - t_ref;
        return c0 + s * (c1 + s * c2);
    }
};

// A stretch [t_begin, t_end] of the ray inside one region of the box. No default member values: the slices' array
// of seven is left unset beyond the pieces in use (zeroing it would cost more than slicing a metaball).
struct RegionPiece {
    double t_begin, t_end;
    // The paper's region vector U per local axis: +1 / −1 beyond the high / low face, 0 within the slab. Inside
    // the box U = 0; face, edge and vertex regions have one, two and three non-zero entries. An axis whose
    // half-size is 0 has no slab, so it is always +1 (the side does not change the distance).
    std::array<int, 3> region;
};

class MetacubeRaySlices {
public:
    // Six face planes, each crossed at most once, cut the support interval into at most seven pieces.
    static constexpr int kMaxPieces = 7;

    // The pieces of `element` along the whole line o + t·dir (t of either sign), or std::nullopt when the line
    // misses the support (or only touches it). A zero direction misses.
    static std::optional<MetacubeRaySlices> slice(const Metacube& element, const Vec3d& origin,
                                                  const Vec3d& direction);

    // The support interval: dist(o + t·dir) ≤ R exactly for t in [t_in, t_out] (up to rounding).
    double t_in() const { return pieces_[0].t_begin; }
    double t_out() const { return pieces_[count_ - 1].t_end; }
    // Sorted, contiguous (each t_end is the next t_begin) and covering [t_in, t_out]; their ends are the breakpoints.
    std::span<const RegionPiece> pieces() const { return {pieces_.data(), std::size_t(count_)}; }
    // dist²(o + t·dir) on `piece` (valid for t in the piece), written about t_ref.
    QuadraticAbout distance_squared(const RegionPiece& piece, double t_ref) const;
    // A metaball's dist² along o + t·dir, written about t_ref: the same bits as distance_squared gives on the one
    // piece of a metaball's slices, without building them. Inline: the march asks it for every metaball it joins.
    static QuadraticAbout metaball_distance_squared(const Vec3d& origin, const Vec3d& direction,
                                                    const Vec3d& centre, double t_ref) {
        return squared_offsets(origin - centre, direction, {0, 0, 0}, {1, 1, 1}, t_ref);  // as metaball() sets them
    }

private:
    MetacubeRaySlices() = default;
    // A metaball's single piece, between the roots t_in < t_out of its support sphere.
    static MetacubeRaySlices metaball(const Vec3d& origin, const Vec3d& direction, const Vec3d& centre, double t_in,
                                      double t_out);
    std::array<int, 3> region_at(double t) const;
    // Σ over the axes with region[k] ≠ 0 of (local_origin[k] + local_direction[k]·t − region[k]·half_size[k])²,
    // expanded about t_ref.
    static QuadraticAbout squared_offsets(const Vec3d& local_origin, const Vec3d& local_direction,
                                          const Vec3d& half_size, const std::array<int, 3>& region, double t_ref) {
        QuadraticAbout q{t_ref};
        for (int k = 0; k < 3; ++k) {
            if (region[k] == 0) continue;
            const double v = local_direction[k];
            const double a = local_origin[k] + v * t_ref - region[k] * half_size[k];
            q.c0 += a * a;
            q.c1 += 2 * a * v;
            q.c2 += v * v;
        }
        return q;
    }

    Vec3d local_origin_, local_direction_, half_size_;
    std::array<RegionPiece, kMaxPieces> pieces_;  // [0, count_) are set; the rest is never read
    int count_ = 0;
};

}  // namespace isotrace
