#pragma once
// Barr's global deformations composed in the paper's order X' = TR·BE·TW·TA·X (eq. 6): the stages are applied
// to the undeformed superquadric first to last, the placement (TR) afterwards. Each stage knows its inverse
// (eq. 7), its Jacobian, and how boxes map through it both ways; the chain keeps a conservative bounding box of
// the object after every stage: the union of the superellipsoid's surface cells carried through the stages by
// interval arithmetic (small cells keep the wrapping effect of interval rotations small). Those stage boxes do two jobs: they bound the deformed object for Embree, and a
// point outside one of them is outside the object, which keeps the inverses away from their singularities (a
// taper's zero scale, a bend's centre).
#include <array>
#include <optional>
#include <variant>
#include <vector>

#include "geometry/superquadric/bend.h"
#include "geometry/superquadric/superellipsoid.h"
#include "geometry/superquadric/taper.h"
#include "geometry/superquadric/twist.h"

namespace isotrace {

using Deformation = std::variant<Taper, Twist, Bend>;

class DeformationChain {
public:
    static constexpr int kMaxStages = 16;
    // Points of every stage: path[0] undeformed, path[k] after stage k.
    using Path = std::array<Vec3d, kMaxStages + 1>;

    explicit DeformationChain(const Superellipsoid& shape);

    // Appends a stage. Throws std::invalid_argument (the stage's problem) when its inverse is not valid over the
    // object as deformed so far, or when the chain is full.
    void append(const Deformation& stage);

    bool empty() const { return stages_.empty(); }
    // Whether every stage maps each solid of revolution about z onto itself (twists only): then such a solid that
    // holds the undeformed object, or lies within it, does the same for the deformed one.
    bool keeps_solids_of_revolution() const { return keeps_solids_of_revolution_; }
    // A cone about z that holds the deformed object (the undeformed one's cylinder carried through the stages), where
    // the stages keep one (twists and one taper, no bend).
    const std::optional<ConeAboutZ>& enclosing_cone() const { return cone_; }
    // The annular sector about the last stage's centre that holds the deformed object, when that stage is a bend
    // and the object lies within its region.
    const std::optional<BendSector>& enclosing_sector() const { return sector_; }
    // The gauge levels s up to which the deformed sublevel set {G∘D⁻¹ ≤ s} is known to be convex: every level for a
    // convex shape undeformed or only twisted with round cross-sections, those of Taper::convex_levels for a taper of
    // one (twisted before or after, if round), none (0) otherwise. A ray from a point of such a level (outside the
    // object) that moves strictly outward never meets the object.
    double convex_levels() const { return convex_levels_; }
    std::size_t heap_bytes() const {
        return stages_.capacity() * sizeof(Deformation) + boxes_.capacity() * sizeof(IntervalBox);
    }
    std::size_t size() const { return stages_.size(); }
    const IntervalBox& undeformed_box() const { return boxes_.front(); }
    const IntervalBox& deformed_box() const { return boxes_.back(); }

    // What a walk back does beyond the undeformed box (stage 0), which no inverse needs: `Outside` counts those
    // points as outside the object, as beyond every other stage box; `Gauge` walks on (the gauge is defined
    // everywhere, above 1 there), so that the field along a ray stays continuous across that box's faces, which the
    // crossing search's bound of g′ needs (a stretch cut by a face has none).
    enum class BeyondUndeformedBox { Outside, Gauge };

    Vec3d forward(const Vec3d& p) const;
    // The undeformed point of q, or nothing when q lies outside a stage box (then it is outside the object; an
    // undeformed object has no box to leave).
    std::optional<Vec3d> inverse(const Vec3d& q, BeyondUndeformedBox beyond = BeyondUndeformedBox::Outside) const;
    // inverse(q, Gauge), and `velocity` (of a curve through q) carried back to the undeformed point's velocity.
    std::optional<Vec3d> inverse_along(const Vec3d& q, Vec3d& velocity) const;
    // The point at every stage of the inverse of q, without the stage-box checks (for normals at surface points).
    Path inverse_path(const Vec3d& q) const;
    // The boxes of an inverse walk of a box: stage[k] bounds the points of its part inside every stage box after k
    // stages (stage[0] undeformed); `clipped` tells whether some of the box was cut away (those points are outside
    // the object).
    struct InverseBoxes {
        std::array<IntervalBox, kMaxStages + 1> stage;
        bool clipped = false;
    };
    // Walks `box` back through the stages into `boxes`; false when no part of it lies inside every stage box.
    bool inverse_boxes(IntervalBox box, InverseBoxes& boxes,
                       BeyondUndeformedBox beyond = BeyondUndeformedBox::Outside) const;
    // For a curve q(t) in the walked box with q'(t) in `tangent`: a bound of d/dt G(D⁻¹(q(t))), G the superellipsoid's
    // gauge, valid where nothing was clipped; unbounded where the gauge's gradient is.
    Interval gauge_slope(const InverseBoxes& boxes, IntervalBox tangent) const;
    // gauge_slope along the three coordinate axes: a bound of the gradient of G∘D⁻¹ over the walked box.
    IntervalBox gauge_gradient(const InverseBoxes& boxes) const;
    // inverse_boxes' undeformed box (stage[0]), or nothing; `clipped` as there.
    std::optional<IntervalBox> inverse_box(const IntervalBox& box, bool& clipped) const;
    // The outward normal at path[size()] from the undeformed normal at path[0] (unit length).
    Vec3d deform_normal(const Path& path, const Vec3d& undeformed_normal) const;

private:
    // The shared inverse walk, last stage first: each stage's preimage is invert(index, stage, image), and the
    // walk returns the undeformed point; nullopt at the first stage box that does not contain the point when
    // `check_boxes` (the undeformed one as `beyond` says). Keeps only the current point (the search's point
    // evaluations fill no path).
    template <class Invert>
    std::optional<Vec3d> walk_inverse(const Vec3d& q, bool check_boxes, BeyondUndeformedBox beyond,
                                      Invert&& invert) const;

    // gauge_slope with the gauge's gradient range over the undeformed box already taken.
    Interval slope_with(const InverseBoxes& boxes, const IntervalBox& gradient, IntervalBox tangent) const;

    // Recomputes boxes_ for the current stages (at construction only, so the cells need not be kept).
    void compute_stage_boxes();

    Superellipsoid shape_;
    std::vector<Deformation> stages_;
    std::vector<IntervalBox> boxes_;  // boxes_[k] bounds the object after k stages, widened slightly
    Interval heights_;  // the object's heights after the stages so far
    bool keeps_solids_of_revolution_ = true;
    std::optional<ConeAboutZ> cone_;
    std::optional<BendSector> sector_;
    double convex_levels_;
};

}  // namespace isotrace
