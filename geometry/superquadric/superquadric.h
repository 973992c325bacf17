#pragma once
// One superquadric primitive: a superellipsoid, its chain of Barr deformations, and its placement (the paper's
// TR: local frame → the shape's space). Rays are intersected in the local deformed frame, where the placement
// keeps t unchanged, and the surface is found as the sign changes of g = G(D⁻¹(p(t))) − 1 along the ray
// (G the superellipsoid's gauge, D the deformation chain):
// - undeformed with ε1 = ε2 = 1: an ellipsoid, intersected in closed form (a quadratic);
// - otherwise: the ray is cut at the local coordinate planes when undeformed (where F changes form), then each
//   piece is searched by interval subdivision (crossing_search.h) with the bounds of g and g′ along the ray
//   (superquadric_along_ray.h);
// - deformed: only the ray's stretches through the cells of the surface shell (surface_shell.h) are searched, cell
//   by cell, with the bounds each cell keeps (shell_cell_bounds.h) asked before those along the ray; an occlusion
//   query settles a run of such cells from outside to inside, as the cells without surface beside it tell, at once;
//   first comes a bound the stages keep (the round forms of the quadrics below for twists, which every turn about z
//   keeps; a cone about z with a taper; an annular sector about a final bend's centre): a ray that misses it is
//   settled, one that reaches the inscribed quadric of twists is blocked, and the walk covers only the part of the
//   ray from where it first enters the bound to where it last leaves it;
// - undeformed and convex (ε1, ε2 ≤ 2): g is convex along the ray, and Newton marches find its crossings without
//   bounds (convex_crossings.h), from where the ray enters and leaves two quadrics around the solid
//   (Superellipsoid::enclosing_stretch), the search above taking over only near tangent contacts;
// - undeformed occlusion queries, whatever the exponents: a ray that misses those quadrics is not blocked, and one
//   that reaches an ellipsoid inscribed in the solid from outside is, without a point value; one that passes beside
//   it is blocked by one value inside the solid, where it comes nearest the centre (convex shapes) or where it
//   crosses a coordinate plane within the quadrics (the others: a star's arms lie about those planes);
// - deformed occlusion queries from outside (but twists'): blocked where the middle of their stretch through the
//   bound lies inside, as the shell's cell there tells or one value in a surface cell;
// - undeformed with ε1, ε2 ≥ 2: g is concave on each piece between the coordinate planes, and tangent cutting
//   planes settle each piece without bounds (concave_crossings.h), again the search taking over near tangents;
// - undeformed with one exponent on each side of 2: the search takes bounds of a difference of convex functions
//   with g's sign (difference_of_convex.h) instead of interval bounds.
#include <optional>
#include <vector>

#include "geometry/field/crossing_search.h"
#include "geometry/superquadric/deformation_chain.h"
#include "geometry/superquadric/superellipsoid.h"
#include "geometry/superquadric/surface_shell.h"
#include "renderer/math/transform.h"

namespace isotrace {

class SuperquadricAlongRay;

struct SuperquadricWork {
    CrossingSearchWork search;
    // Every value of g the search took along the ray, also those at the ends of pieces and cells and the tests
    // before the search (its own count has only the values it asks for).
    std::uint64_t point_values = 0;
    std::uint64_t quadratic_solves = 0;  // an ellipsoid's closed form
};

class Superquadric {
public:
    // Crossings closer together than this fraction of the object's size may be taken for a grazing contact.
    static constexpr double kRelativeResolution = 1e-7;

    Superquadric(Superellipsoid shape, DeformationChain deformation, Transform placement);

    const Superellipsoid& shape() const { return shape_; }
    const DeformationChain& deformation() const { return deformation_; }
    const Transform& placement() const { return placement_; }
    // Places the object by `to_world` after its current placement.
    void transform(const Transform& to_world) { placement_ = to_world * placement_; }

    // Axis-aligned box around the placed, deformed object (conservative).
    IntervalBox bounds() const;
    // G(D⁻¹(p)) − 1 at a point of the shape's space: negative inside, 0 on the surface.
    double field(const Vec3d& point) const;
    // field(point) < 0, without the gauge where the point lies outside the deformed box (the surface lies strictly
    // inside that box, so the field is positive there).
    bool contains(const Vec3d& point) const;
    // The field at a point of the local deformed frame (before the placement); with `Gauge`, continued beyond the
    // undeformed box by the gauge (the crossing search's field) instead of 1.
    double local_field(const Vec3d& local, DeformationChain::BeyondUndeformedBox beyond =
                                               DeformationChain::BeyondUndeformedBox::Outside) const;
    // Contains local_field over a box of the local deformed frame (interval inverse of the chain, then the gauge's
    // range; points outside a stage box count as outside, 1). What its callers ask is whether zero is excluded: the
    // upper end, which only tells a box inside the object, is left infinite where the lower one is already at least
    // zero or part of the box was clipped (outside the object), without the gauge at the box's far corner.
    Interval local_field_range(const IntervalBox& local) const;
    // The same over a box whose inverse walk through the chain found some of it inside every stage box.
    Interval field_range(const DeformationChain::InverseBoxes& walked) const;
    // The field of the search (continued beyond the undeformed box by the gauge) at `centre` and bounds of its
    // gradient over `cell`, a box of the local deformed frame: what the surface shell keeps of each of its cells.
    ShellCellBounds cell_bounds(const IntervalBox& cell, const Vec3d& centre) const;
    // g at the centre of a box of the local deformed frame (continued beyond the undeformed box by the gauge) and
    // bounds of its gradient there, for the surface shell's cells; not `known` where a bound is not finite.
    ShellCellBounds cell_bounds(const IntervalBox& cell) const;
    // field() continued beyond the deformed box by the distance to it, in the local deformed frame (field() is a
    // constant 1 out there, the ray tracer needing only its sign): negative inside, continuous and rising outward.
    double continued_field(const Vec3d& point) const;
    // True only when no point within `distance` of `point` (both in the shape's space) is inside or on the
    // surface; decided for undeformed convex shapes (whose gauge is a norm), false otherwise.
    bool certainly_outside(const Vec3d& point, double distance) const;
    // Outward unit normal at a surface point of the shape's space: J⁻ᵀ·∇F carried through the chain, then the
    // placement's inverse transpose.
    Vec3d normal(const Vec3d& point) const;
    // A point of the surface from the paper's parametric form (eq. 1), deformed and placed.
    Vec3d surface_point(double eta, double omega) const;

    // The first crossing of origin + t·direction with the surface for t in [t_min, t_max].
    std::optional<double> first_crossing(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                         SuperquadricWork& work) const;
    // The same crossing, with whether the ray enters there.
    std::optional<Crossing> first_of_crossings(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                               SuperquadricWork& work) const;
    // Whether a crossing lies in (t_min, t_max) with float(t) < float(t_max) — first_crossing's answer — settled by
    // the first stretch whose ends differ in sign when it lies inside the range, without isolating or refining its
    // crossing (an occlusion query).
    bool blocks(const Vec3d& origin, const Vec3d& direction, double t_min, float t_max, SuperquadricWork& work) const;
    // Whether the ray lies inside throughout (t, past] after entering at t: g deep below zero at past, and between
    // them convexity (undeformed exponents ≤ 2) or a bound of g′ below zero.
    bool inside_after_entry(const Vec3d& origin, const Vec3d& direction, double t, double past) const;
    // Whether a deformed shape's box holds the point: an occlusion query from there (a shadow ray leaving its
    // surface) must prove the ray's way out through the shell, a costly search that is put off until nothing else
    // blocks the ray (OcclusionPass). Undeformed shapes settle such rays by their quadrics or one point value.
    bool starts_within_deformed_box(const Vec3d& origin, const Vec3d& direction, double t_near) const {
        return !deformation_.empty() &&
               deformation_.deformed_box().contains(placement_.inverse_point(origin + direction * t_near));
    }
    // All crossings in [t_min, t_max], in increasing t, appended to `out`.
    void crossings(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                   std::vector<Crossing>& out, SuperquadricWork& work) const;

private:
    // Visits the crossings in [t_min, t_max] in order until visit(Crossing) returns false (after the first when
    // `first_only`); Bracketed or SignChange: the general search reports brackets unrefined (the closed forms and
    // marches are exact anyway), with SignChange the first stretch whose ends differ in sign as it is.
    template <CrossingPrecision precision, class Visit>
    void search(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max, bool first_only,
                SuperquadricWork& work, Visit&& visit) const;

    // The deformed shapes' search: cell by cell along the ray's runs through the surface shell, each cell's stretch
    // settled by the cell's bounds where they suffice, by the general search (with the cell's bounds first) elsewhere.
    // `enters_box`: the line enters the deformed box through a face at t0, outside the object.
    template <CrossingPrecision precision, class Visit>
    void search_shell(const SuperquadricAlongRay& ray, double t0, double t1, bool enters_box, double resolution,
                      SuperquadricWork& work, Visit&& visit) const;

    Superellipsoid shape_;
    DeformationChain deformation_;
    Transform placement_;
    SurfaceShell shell_;  // deformed only: where the search needs to look
};

}  // namespace isotrace
