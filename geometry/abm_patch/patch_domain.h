#pragma once
// The parameter domain of an attribute-based multi-sided patch (Gao & Rockwood): a convex polygon whose sides are
// the footprints of the boundary curves. For a domain point x each side i gives its distance d_i(x) (zero on the
// side, the weight W_i = 1/d_i^p grows toward it) and the parameter s_i(x) ∈ [0, 1] of x's footprint on it (the
// curve is evaluated there), with their gradients for analytic normals.
#include <memory>
#include <string>
#include <vector>

namespace isotrace {

struct DomainPoint {
    double x = 0, y = 0;
};

struct Footprint {
    double distance = 0;               // d_i(x) ≥ 0
    double distance_dx = 0, distance_dy = 0;
    double parameter = 0;              // s_i(x) ∈ [0, 1]
    double parameter_dx = 0, parameter_dy = 0;
};

class PatchDomain {
public:
    static constexpr int kMaxSides = 8;

    virtual ~PatchDomain() = default;

    virtual std::string name() const = 0;
    // Corners in loop order: side i runs from corner i to corner i + 1 (mod N), and on it s_i goes from 0 to 1
    // linearly, so that a closed loop of curves, each running into the next, is the patch boundary.
    const std::vector<DomainPoint>& corners() const { return corners_; }
    int sides() const { return int(corners_.size()); }
    // The interior point where all distances are equal (incentre); the patch is the mean of its attributes there.
    virtual DomainPoint centre() const = 0;
    // Fills out[0 … N−1] for a point of the domain (distances of points outside are clamped to 0).
    virtual void footprints(DomainPoint x, Footprint* out) const = 0;

    // The point of side i where s_i = t.
    DomainPoint on_side(int side, double t) const;
    // +1 when the corners run counter-clockwise, −1 when clockwise (the paper's domains).
    double orientation() const;

protected:
    explicit PatchDomain(std::vector<DomainPoint> corners) : corners_(std::move(corners)) {}

private:
    std::vector<DomainPoint> corners_;
};

// The paper's three-sided domain, the right triangle {u, v ≥ 0, u + v ≤ 1} with corners (0,0), (0,1), (1,0):
// d = (u, (1 − u − v)/√2, v), s = (v, (u − v + 1)/2, 1 − u) — orthogonal projections onto the sides.
std::unique_ptr<PatchDomain> right_triangle_domain();
// The paper's four-sided domain, the unit square with corners (0,0), (0,1), (1,1), (1,0):
// d = (u, 1 − v, 1 − u, v), s = (v, u, 1 − v, 1 − u).
std::unique_ptr<PatchDomain> unit_square_domain();
// The regular N-gon (3 ≤ N ≤ 8) of circumradius 1 about the origin, corners counter-clockwise from
// (cos θ0, sin θ0), θ0 = −π/2 − π/N (side 0 at the bottom): d_i = distance to the line of side i,
// s_i = d_{i−1} / (d_{i−1} + d_{i+1}). Throws std::invalid_argument for N outside 3 … 8.
std::unique_ptr<PatchDomain> regular_polygon_domain(int sides);

}  // namespace isotrace
