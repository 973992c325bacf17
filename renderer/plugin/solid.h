#pragma once
// Solid: a shape that encloses a volume, so constructive solid geometry can combine it (Roth's ray
// classification: every solid reports the spans of a ray that lie inside it, and CSG combines the span lists per
// operator). A shape that is a solid derives from both Shape and Solid; CSG finds it with dynamic_cast.
#include <embree3/rtcore.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "renderer/embree/query_scratch.h"
#include "renderer/math/vec3.h"

namespace isotrace {

// One end of an inside span.
struct BoundaryPoint {
    static constexpr std::uint32_t kCut = std::numeric_limits<std::uint32_t>::max();

    double t = 0;
    Vec3d normal{0, 0, 1};        // outward unit normal in the shape's space (meaningless for a cut end, and where
                                  // the solid defers it: Solid::boundary_normal)
    std::uint32_t primitive = 0;  // the shape's primitive (element, triangle, ...) the point lies on; kCut when
                                  // the span was cut at the query range instead of ending on the surface
    std::uint32_t part = 0;       // for composite solids (CSG): which leaf surface the point lies on
    // How far t may be from where the surface really is, beyond the relative tolerance every CSG event gets
    // (kCoincidentRelative): 0 for solids computed in double, more for those whose crossings come from Embree in
    // float (meshes). Another operand's surface within it is the same surface.
    double t_tolerance = 0;

    bool on_surface() const { return primitive != kCut; }
};

// origin + t·direction is inside the solid for t in (enter.t, exit.t).
struct InsideSpan {
    BoundaryPoint enter, exit;
};

// What Solid::leading_span could tell about the first inside span along a ray.
struct LeadingSpan {
    enum class Outcome { Unsure, None, Found };
    Outcome outcome = Outcome::Unsure;
    InsideSpan span;  // when Found

    bool found() const { return outcome == Outcome::Found; }
};

class Solid {
public:
    virtual ~Solid() = default;

    // Empty when the shape really encloses a volume; otherwise why not (e.g. a mesh with boundary edges), for the
    // error that rejects it as a CSG operand.
    virtual std::string solid_problem() const { return {}; }

    // Called once, after any bake and before the first inside_spans, by the CSG shape that owns the solid (a
    // mesh builds its own Embree scene here, say).
    virtual void prepare_span_queries(RTCDevice device) { (void)device; }

    // Appends to `spans`, in increasing t, the spans of origin + t·direction (direction not necessarily unit
    // length) that lie inside the solid, clipped to [t_min, t_max]: disjoint, non-empty, ends on the surface
    // except where clipped (BoundaryPoint::kCut). A solid that needs buffers takes a level of `scratch`, the
    // query's (nothing else is written), so concurrent queries with scratches of their own are safe.
    virtual void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                              std::vector<InsideSpan>& spans, QueryScratch& scratch) const = 0;

    // The first point in (t_near, t_far) where the ray crosses the surface: by default the first surface end of
    // inside_spans over that range. Solids that can settle it with less work override it.
    virtual std::optional<BoundaryPoint> first_surface_point(const Vec3d& origin, const Vec3d& direction,
                                                             double t_near, double t_far, QueryScratch& scratch) const;
    // The first span of inside_spans over [t_min, t_max] when the solid can tell it without listing the others (its
    // enter bit for bit that span's, its exit no later than that span's: the ray is inside at least up to there), or
    // that there is none. Unsure by default: the caller then asks inside_spans.
    virtual LeadingSpan leading_span(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                     QueryScratch& scratch) const {
        (void)origin, (void)direction, (void)t_min, (void)t_max, (void)scratch;
        return {};
    }
    // Whether the span ends on part `part` leave their normal to boundary_normal: a solid whose normals cost more
    // than its span ends (a CSG asks for many ends and shows one) computes them only for the end it is asked about.
    virtual bool defers_normals(std::uint32_t part) const {
        (void)part;
        return false;
    }
    // The outward unit normal at `end`, a surface end of this solid's inside_spans or first_surface_point along the
    // same ray: end.normal unless the solid defers it, and then bit for bit what it would have stored there.
    virtual Vec3d boundary_normal(const Vec3d& origin, const Vec3d& direction, const BoundaryPoint& end) const {
        (void)origin, (void)direction;
        return end.normal;
    }
    // True only when no point within `distance` of `point` lies inside or on the solid (false when unsure): lets a
    // CSG accept a surface point of one operand without listing the spans of the others.
    virtual bool certainly_outside(const Vec3d& point, double distance) const {
        (void)point, (void)distance;
        return false;
    }
    // Whether every span end is computed in double with no tolerance of its own (BoundaryPoint::t_tolerance 0);
    // a float mesh's are not.
    virtual bool exact_boundaries() const { return true; }
};

// The first end of `spans` (in increasing t) that lies on the surface strictly inside (t_near, t_far).
std::optional<BoundaryPoint> first_surface_crossing(std::span<const InsideSpan> spans, double t_near, double t_far);

}  // namespace isotrace
