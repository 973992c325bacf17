#pragma once
// A ring torus: the points at distance `minor_radius` from the circle of radius `major_radius` around the frame's
// axis (AxialFrame, origin at the centre). A line meets it where a quartic vanishes; it is solved in units of the
// major radius with the line's origin moved to its point nearest the centre (which makes the cubic coefficient
// vanish and keeps far rays as precise as near ones), its roots found by the polynomial toolkit's monotone-interval
// finder inside the bounding sphere's chord, and each polished by Newton steps on the exact distance to the tube.
// docs/decisions.md ("Torus roots") gives the reasons.
#include <array>

#include "geometry/cone/axial_frame.h"

namespace isotrace {

struct Torus : AxialFrame {
    double major_radius = 1;    // > minor_radius
    double minor_radius = 0.25;  // > 0
};

// Where the line origin + t·direction crosses the surface, ascending: up to four. A contact without a crossing
// (a grazing line, within rounding) is left out.
struct TorusCrossings {
    int count = 0;
    std::array<double, 4> t{};
};

// The crossings with t in [t_min, t_max]; `first_only` stops at the first.
TorusCrossings torus_crossings(const Torus& torus, const Vec3d& origin, const Vec3d& direction, double t_min,
                               double t_max, bool first_only);

// The exact signed distance to the surface (negative inside the tube) and its gradient (the outward unit normal on
// the surface).
double torus_distance(const Torus& torus, const Vec3d& p);
Vec3d torus_gradient(const Torus& torus, const Vec3d& p);

// The axis-aligned box of the torus.
void torus_bounds(const Torus& torus, Vec3d& lower, Vec3d& upper);

}  // namespace isotrace
