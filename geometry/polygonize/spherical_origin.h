#pragma once
// Setting up a spherical lattice for a field: the origin, corrected off the surface, and the radial range.
//
// Origin correction (the paper's §III.3, with its slip fixed): the paper steps x₁ = x₀ + δ∇f, which only ever moves
// outwards. Here the origin steps x_{k+1} = x_k + δ·s·∇f/|∇f| with s = the sign of f(x₀) (−1, inside, when f is
// exactly 0): it stays on the side it is already on, which is the nearer one, and leaves the surface along the
// shortest way. δ is one finest cell of the bounds (max extent / 2^L); steps continue until the origin is clear:
// the estimated distance |f|/|∇f| reaches two cells, and f keeps its sign at 26 probes one cell away (up, down,
// across the faces, edges and corners of a cube). Where the gradient is zero or undefined (the saddle where two
// blobs touch, a hard cube's flat field) the probes alone decide, and the step goes to the probe deepest on the
// origin's side. At most kMaxOriginSteps steps; `converged` says whether the origin ended clear.
#include <optional>

#include "geometry/polygonize/spherical_lattice.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

constexpr int kMaxOriginSteps = 256;
// r_min's floor, as a fraction of r_max (spherical_range).
constexpr double kMinRadiusFraction = 1e-3;

struct OriginCorrection {
    Vec3d origin;
    int steps = 0;
    bool converged = false;  // the origin ended clear of the surface
};

OriginCorrection correct_origin(const ImplicitField& field, const Vec3d& origin, int depth);

// r_max reaches past every corner of the field's bounds; r_min is 0.9 × the largest radius (found by bisection on
// may_reach_surface) around the origin that holds no surface, but at least kMinRadiusFraction·r_max: an origin on
// the surface
// gets that floor, and the surface near it falls inside r_min — the mesh then has a hole there (the paper's
// Fig. 5 failure, which origin correction avoids).
SphericalRange spherical_range(const ImplicitField& field, const Vec3d& origin);

}  // namespace isotrace
