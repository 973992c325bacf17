#pragma once
// The box of a field's surface, found from may_reach_surface and value_range alone, so that a lattice spans the surface and not
// whatever a field's bounds() promise (a blob group's kernel supports reach well past its surface; an element of
// negligible weight adds its whole support).
//
// For each of the six faces a best-first search over an octree of field.bounds() pops the cell that reaches
// farthest in that direction; a cell that cannot reach the surface (may_reach_surface, or value_range of one sign)
// is dropped, others are split, and the first
// cell of the finest level popped gives the face: every cell still queued reaches less far, every dropped one has
// no surface. The result is conservative (it contains the whole surface, as far as may_reach_surface is) and
// tight to a finest cell plus those tests' slack.
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

// Levels of the search: the finest cells are field.bounds() / 2^kSurfaceBoundsDepth along each axis.
constexpr int kSurfaceBoundsDepth = 10;

// field.bounds() when that is empty or not finite, or when no cell may hold surface; otherwise a box inside it
// grown by a finest cell.
FieldBox surface_bounds(const ImplicitField& field);

// `inner` with surface_bounds(inner) as its bounds (the rest forwarded); `inner` must outlive it.
class SurfaceBoundedField final : public ImplicitField {
public:
    explicit SurfaceBoundedField(const ImplicitField& inner) : inner_(inner), bounds_(surface_bounds(inner)) {}
    double value(const Vec3d& p) const override { return inner_.value(p); }
    void values(std::span<const Vec3d> points, std::span<double> out) const override { inner_.values(points, out); }
    Vec3d gradient(const Vec3d& p) const override { return inner_.gradient(p); }
    FieldBox bounds() const override { return bounds_; }
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        return bounds_.distance(centre) <= radius && inner_.may_reach_surface(centre, radius);
    }
    Interval value_range(const IntervalBox& box) const override { return inner_.value_range(box); }
    Interval slope_range(const IntervalBox& box, const Vec3d& direction) const override {
        return inner_.slope_range(box, direction);
    }

private:
    const ImplicitField& inner_;
    FieldBox bounds_;
};

}  // namespace isotrace
