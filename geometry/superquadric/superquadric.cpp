#include "geometry/superquadric/superquadric.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/field/concave_crossings.h"
#include "geometry/field/convex_crossings.h"
#include "geometry/sphere/sphere_intersection.h"
#include "geometry/superquadric/recent_samples.h"
#include "geometry/superquadric/superquadric_along_ray.h"
#include "renderer/math/line_box_clip.h"

namespace isotrace {
namespace {

double largest_extent(const IntervalBox& box) {
    return std::max({box.x.width(), box.y.width(), box.z.width()});
}

// Every value of one sign (g < 0 inside): what a bound hands the search where another test proved that g keeps
// that sign over a stretch.
Interval of_sign(bool inside) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return inside ? Interval{-inf, -std::numeric_limits<double>::denorm_min()} : Interval{0, inf};
}

}  // namespace

Superquadric::Superquadric(Superellipsoid shape, DeformationChain deformation, Transform placement)
    : shape_(shape), deformation_(std::move(deformation)), placement_(placement) {
    if (!deformation_.empty()) shell_ = SurfaceShell(deformation_.deformed_box());
}

IntervalBox Superquadric::bounds() const {
    const IntervalBox& local = deformation_.deformed_box();
    IntervalBox box = IntervalBox::point(placement_.point(local.lower()));
    for (int corner = 1; corner < 8; ++corner) {
        const Vec3d p((corner & 1 ? local.x.hi : local.x.lo), (corner & 2 ? local.y.hi : local.y.lo),
                      (corner & 4 ? local.z.hi : local.z.lo));
        box.extend(placement_.point(p));
    }
    return box;
}

double Superquadric::local_field(const Vec3d& local, DeformationChain::BeyondUndeformedBox beyond) const {
    const std::optional<Vec3d> undeformed = deformation_.inverse(local, beyond);
    return undeformed ? shape_.gauge(*undeformed) - 1 : 1;  // outside a stage box is outside the object
}

Interval Superquadric::local_field_range(const IntervalBox& local) const {
    DeformationChain::InverseBoxes walked;
    if (!deformation_.inverse_boxes(local, walked)) return Interval{1, 1};
    return field_range(walked);
}

Interval Superquadric::field_range(const DeformationChain::InverseBoxes& walked) const {
    const IntervalBox& undeformed = walked.stage[0];
    const double lo = shape_.least_gauge(undeformed) - 1;
    if (walked.clipped || lo >= 0) return {lo, std::numeric_limits<double>::infinity()};
    return {lo, shape_.most_gauge(undeformed) - 1};
}

ShellCellBounds Superquadric::cell_bounds(const IntervalBox& cell, const Vec3d& centre) const {
    ShellCellBounds bounds;
    constexpr DeformationChain::BeyondUndeformedBox kBeyond = DeformationChain::BeyondUndeformedBox::Gauge;
    // The cell's part within the deformed box: the search asks no point beyond it (SuperquadricAlongRay), and an
    // outer cell, enlarged past the box's face, would otherwise count as clipped and keep no gradient bound.
    IntervalBox inside = cell;
    DeformationChain::InverseBoxes walked;
    if (!clip_box(inside, deformation_.deformed_box()) || !deformation_.inverse_boxes(inside, walked, kBeyond) ||
        walked.clipped)
        return bounds;
    bounds.gradient = deformation_.gauge_gradient(walked);
    if (!bounds.gradient.is_finite()) return bounds;
    bounds.centre = centre;
    bounds.value = local_field(centre, kBeyond);
    bounds.known = true;
    return bounds;
}

double Superquadric::field(const Vec3d& point) const { return local_field(placement_.inverse_point(point)); }

bool Superquadric::contains(const Vec3d& point) const {
    const Vec3d local = placement_.inverse_point(point);
    return deformation_.deformed_box().contains(local) && local_field(local) < 0;
}

double Superquadric::continued_field(const Vec3d& point) const {
    const Vec3d local = placement_.inverse_point(point);
    const Vec3d nearest = deformation_.deformed_box().nearest(local);
    return local_field(nearest) + length(local - nearest);
}

// For ε1, ε2 ≤ 2 the gauge G is a norm of the radii-scaled coordinates, at most their 1-norm, so a step v changes
// it by at most ‖v/radii‖₁ ≤ √3·|v|/(smallest radius): G − 1 above that for the whole distance keeps the point out.
bool Superquadric::certainly_outside(const Vec3d& point, double distance) const {
    if (!deformation_.empty() || !shape_.is_convex()) return false;
    const double scale = placement_.similarity_scale();
    if (!(scale > 0)) return false;
    const Vec3d& r = shape_.radii();
    const double reach = std::sqrt(3.0) * distance / (scale * std::min({r.x, r.y, r.z}));
    constexpr double kRounding = 1e-12;  // of the gauge and the placement, relative to the gauge's unit
    const Vec3d local = placement_.inverse_point(point);
    // Beside the box, its gauge settles it without the shape's.
    return shape_.box_gauge(local) - 1 > reach + kRounding || shape_.gauge(local) - 1 > reach + kRounding;
}

Vec3d Superquadric::normal(const Vec3d& point) const {
    const DeformationChain::Path path = deformation_.inverse_path(placement_.inverse_point(point));
    const Vec3d local = deformation_.deform_normal(path, shape_.normal(path[0]));
    return normalize(placement_.normal(local));
}

Vec3d Superquadric::surface_point(double eta, double omega) const {
    return placement_.point(deformation_.forward(shape_.surface_point(eta, omega)));
}

template <CrossingPrecision precision, class Visit>
void Superquadric::search(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max, bool first_only,
                          SuperquadricWork& work, Visit&& visit) const {
    const SuperquadricAlongRay ray(*this, origin, direction, &work.point_values);
    const Vec3d &o = ray.local_origin(), &d = ray.local_direction();
    const IntervalBox& box = deformation_.deformed_box();
    const std::optional<LineBoxClip> clip = clip_line_to_box(box.lower(), box.upper(), o, d, t_min, t_max);
    if (!clip) return;
    const double t0 = clip->t_enter, t1 = clip->t_exit;

    if (deformation_.empty() && shape_.is_ellipsoid()) {
        // ε1 = ε2 = 1: an ellipsoid, the unit sphere once lengths are divided by the radii; its closed form (a
        // cancellation-free quadratic) is exact and far cheaper than a march. Other even powers make F − 1 a
        // polynomial along the ray too, but they are convex, and marching them is faster than solving it.
        ++work.quadratic_solves;
        const Vec3d& r = shape_.radii();
        const Vec3d start = o + d * t0;  // in u = t − t0, for precision
        const std::optional<SphereRoots> roots = intersect_sphere({start.x / r.x, start.y / r.y, start.z / r.z},
                                                                  {d.x / r.x, d.y / r.y, d.z / r.z}, {0, 0, 0}, 1);
        if (!roots || !(roots->t0 < roots->t1)) return;  // grazing contacts are misses (docs/decisions.md)
        if (roots->t0 >= 0 && roots->t0 <= t1 - t0 && !visit(Crossing{t0 + roots->t0, true})) return;
        if (roots->t1 >= 0 && roots->t1 <= t1 - t0) visit(Crossing{t0 + roots->t1, false});
        return;
    }
    const bool convex = deformation_.empty() && shape_.is_convex();
    // A ray that starts within the box outside the object and moving away (a ray leaving its surface, as a rule) has
    // no crossing where the level set through its start is convex (DeformationChain::convex_levels): one point value
    // says so, before the quadrics. A convex gauge grows along every direction it does not fall along; a deformed one
    // is only known to have convex level sets, along whose outward normal the start must move strictly.
    if (clip->enter_axis < 0 && deformation_.convex_levels() > 1) {
        const ValueAndDerivative start = ray.value_and_slope(t0);
        if (start.value > 0 && 1 + start.value <= deformation_.convex_levels() &&
            (convex ? start.derivative >= 0 : start.derivative > 0))
            return;
    }
    // A star-like or pinched shape fills little of its quadrics: a ray that enters its box and passes beside its
    // planes is settled before them. (One that starts within the box leaves the shape's surface, as a rule: it
    // starts within the planes too.)
    if (deformation_.empty() && clip->enter_axis >= 0 &&
        shape_.enclosing_polytope().misses(o + d * t0, d, t1 - t0))
        return;
    // Two quadrics hold an undeformed solid (Superellipsoid::enclosing_stretch): a ray that passes beside them is
    // settled at once, and convex shapes' marches start where it enters and leaves them, closer to its crossings than
    // the box's faces. The other shapes take them for occlusion queries only: their searches cut the ray at the
    // coordinate planes, and the pieces' own tests already pass over most of the box. A deformed solid has the bound
    // its stages keep: their round forms for twists, a cone about z with a taper (DeformationChain::enclosing_cone),
    // an annular sector about a final bend's centre (enclosing_sector). Its rays that miss the bound are settled, and
    // the shell is walked only from where they first enter it to where they last leave it.
    double lo = t0, hi = t1;
    const auto narrow = [&](const std::optional<Interval>& around) {
        if (!around) return false;
        if (around->lo > 0) lo = t0 + around->lo;
        if (around->hi < t1 - t0) hi = t0 + around->hi;
        return true;
    };
    const bool turned = !deformation_.empty() && deformation_.keeps_solids_of_revolution();
    // Whether the line is outside where the stretch starts (an occlusion query from outside): beyond the margin of the
    // quadrics or bound that narrowed it, or on the box's face: the widened one of an undeformed shape, where the
    // gauge is at least the largest |xᵢ|/aᵢ, or the deformed box, which holds the solid strictly within.
    const auto outside_at_lo = [&] {
        return lo > t0 || (turned ? clip->enter_axis >= 0 : shape_.box_gauge(o + d * t0) > 1 + 1e-12);
    };
    if (!deformation_.empty() && !turned && deformation_.enclosing_cone() &&
        !narrow(deformation_.enclosing_cone()->stretch(o + d * t0, d, t1 - t0)))
        return;
    if (deformation_.enclosing_sector() && !narrow(deformation_.enclosing_sector()->stretch(o + d * t0, d, t1 - t0)))
        return;
    if ((deformation_.empty() && (convex || precision == CrossingPrecision::SignChange)) || turned) {
        using QuadricForm = Superellipsoid::QuadricForm;
        const QuadricForm form = turned ? QuadricForm::RoundAboutZ : QuadricForm::AlongRadii;
        if (!narrow(shape_.enclosing_stretch(o + d * t0, d, t1 - t0, form))) return;
        // An occlusion query: a ray that is outside at lo and then reaches the inscribed ellipsoid (g < 0) crosses the
        // surface in between, and nowhere before.
        if constexpr (precision == CrossingPrecision::SignChange) {
            if (outside_at_lo()) {
                if (const std::optional<Interval> inside = shape_.inscribed_stretch(o + d * lo, d, hi - lo, form);
                    inside && inside->lo > 0) {
                    const double reached = lo + inside->lo;
                    visit(Crossing{0.5 * (lo + reached), true, lo, reached});
                    return;
                }
                // One that passes beside that ellipsoid may still cross a convex solid (a box's edges): one value
                // where it comes nearest the centre settles most such rays alike. (A star's arms lie away from it.)
                if (convex) {
                    const double nearest = lo + shape_.nearest_to_centre(o + d * lo, d, hi - lo, form);
                    if (nearest > lo && ray.value(nearest) < 0) {
                        visit(Crossing{0.5 * (lo + nearest), true, lo, nearest});
                        return;
                    }
                }
            }
        }
    }
    const bool concave = deformation_.empty() && shape_.is_concave_in_octants();
    const bool mixed = deformation_.empty() && !convex && !concave;
    // The piece being searched, and whether its ends lie on coordinate planes (cusps: no tangents there).
    double piece_lo = t0, piece_hi = t1;
    bool cusp_lo = false, cusp_hi = false;
    RecentSamples<Superellipsoid::GaugeAndDifference> samples;
    const auto mixed_at = [&](double t) -> const Superellipsoid::GaugeAndDifference& {
        return samples.at(t, [&] { return ray.gauge_and_difference(t); });
    };
    // Undeformed, the field is the gauge less 1 (local_field): mixed shapes take it with their parts. An occlusion
    // query asks the cuts' values before their pieces do.
    RecentSamples<double> values;
    const auto value = [&](double t) {
        return mixed ? mixed_at(t).gauge - 1 : values.at(t, [&] { return ray.value(t); });
    };
    const auto value_and_slope = [&](double t) { return ray.value_and_slope(t); };
    const auto sample_at = [&](double t) {
        DifferenceOfConvexSample sample = mixed_at(t).difference;
        if ((t == piece_lo && cusp_lo) || (t == piece_hi && cusp_hi)) sample.convex.slope = sample.subtracted.slope = NAN;
        return sample;
    };
    // Mixed exponents: the chords and tangents of φ's convex parts (difference_of_convex.h) bound far tighter
    // than interval arithmetic; where they settle nothing, the stretch is halved. φ has g's sign but not
    // its slope: a bound of φ′ that excludes zero is handed to the search only as what the search takes from such
    // a bound of g′ — that g changes sign at most once on the stretch.
    const auto bound = [&](double a, double b) {
        if (mixed) {
            const Interval phi = difference_of_convex_range(a, sample_at(a), b, sample_at(b));
            if (phi.lo >= 0 || phi.hi < 0) return of_sign(phi.hi < 0);
            return Interval::unbounded();
        }
        return ray.bound(a, b);
    };
    const auto slope = [&](double a, double b) {
        if (mixed) {
            const Interval phi = difference_of_convex_slope(sample_at(a), sample_at(b));
            return phi.excludes_zero() ? phi : Interval::unbounded();
        }
        return ray.slope_bound(a, b);
    };
    const double resolution = kRelativeResolution * largest_extent(deformation_.deformed_box()) / length(d);
    if (!deformation_.empty()) {
        // Every crossing lies within the bound, and the line is outside where it enters the bound within the box
        // (without a bound, lo and hi are the box's).
        search_shell<precision>(ray, lo, hi, clip->enter_axis >= 0 || lo > t0, resolution, work, visit);
        return;
    }
    if (convex && visit_convex_crossings(lo, hi, value_and_slope, first_only, work.search, visit)) return;

    // F changes form where a coordinate changes sign: cut there, so that on every piece each |xᵢ| is linear and
    // the bound is exact.
    double cuts[5] = {t0};
    int count = 1;
    for (int k = 0; k < 3; ++k) {
        const double t = -o[k] / d[k];
        if (!(t > t0 && t < t1)) continue;
        int at = count++;  // insertion keeps the cuts in order
        for (; at > 1 && cuts[at - 1] > t; --at) cuts[at] = cuts[at - 1];
        cuts[at] = t;
    }
    cuts[count++] = t1;
    // A piece whose stretch lies where the gauge exceeds 1 throughout holds no crossing, and every value the search
    // would take there is positive: it is passed over without its ends' values (a ray missing a star's arms, a
    // shadow ray leaving the surface it starts at).
    double g_start = 0;  // g at the piece's start, taken when a piece needs it
    bool known_start = false;
    const auto outside_throughout = [&](double a, double b) {
        IntervalBox stretch = IntervalBox::point(o + d * a);  // as value() takes the points: it holds all of them
        stretch.extend(o + d * b);
        return shape_.least_gauge(stretch) > 1;
    };
    // An occlusion query from outside (beyond the quadrics, or outside at the start) is settled by any cut inside the
    // quadrics where g < 0: a star's arms and a pinched shape's bulk lie about the coordinate planes, and a ray that
    // crosses the solid crosses one there as a rule. The values are the search's own at the pieces' ends.
    if constexpr (precision == CrossingPrecision::SignChange) {
        if (!convex && outside_at_lo())
            for (int i = 1; i + 1 < count; ++i)
                if (cuts[i] > lo && cuts[i] < hi && value(cuts[i]) < 0) {
                    visit(Crossing{0.5 * (lo + cuts[i]), true, lo, cuts[i]});
                    return;
                }
    }
    for (int i = 0; i + 1 < count; ++i) {
        if (outside_throughout(cuts[i], cuts[i + 1])) {
            known_start = false;
            continue;
        }
        if (!known_start) g_start = value(cuts[i]);
        known_start = true;
        const double g_end = value(cuts[i + 1]);
        piece_lo = cuts[i], piece_hi = cuts[i + 1], cusp_lo = i > 0, cusp_hi = i + 2 < count;
        if (concave) {
            const ConcaveOutcome outcome =
                visit_concave_crossings<precision>(piece_lo, piece_hi, g_start, g_end, cusp_lo, cusp_hi, resolution,
                                                   value_and_slope, work.search, visit);
            if (outcome == ConcaveOutcome::Stopped) return;
            if (outcome == ConcaveOutcome::Settled) {
                g_start = g_end;
                continue;
            }
        }
        if (!search_crossings<precision>(cuts[i], cuts[i + 1], g_start, g_end, resolution, convex, value, bound,
                                         slope, work.search, visit, value_and_slope))
            return;
        g_start = g_end;
    }
}

template <CrossingPrecision precision, class Visit>
void Superquadric::search_shell(const SuperquadricAlongRay& ray, double t0, double t1, bool enters_box,
                                double resolution, SuperquadricWork& work, Visit&& visit) const {
    const Vec3d &o = ray.local_origin(), &d = ray.local_direction();
    RecentSamples<double> values;
    const auto value = [&](double t) { return values.at(t, [&] { return ray.value(t); }); };
    const auto value_and_slope = [&](double t) { return ray.value_and_slope(t); };
    const auto range = [&](const IntervalBox& cell) { return local_field_range(cell); };
    const auto bounds_of = [&](const IntervalBox& cell, const Vec3d& centre) { return cell_bounds(cell, centre); };
    using Side = SurfaceShell::Side;
    // An occlusion query that enters from outside is settled where the middle of its stretch lies inside: the shell's
    // cell there tells so without a value, or one value does where the cell can hold the surface (a ray through the
    // solid). A cell outside tells nothing, and the walk goes on as if the middle had not been asked. (A twisted
    // shape's rays that pass deep through it were settled before, by the quadric inscribed in it.)
    if constexpr (precision == CrossingPrecision::SignChange) {
        const double middle = 0.5 * (t0 + t1);
        if (enters_box && middle > t0 && !deformation_.keeps_solids_of_revolution()) {
            const Side side = shell_.side_at(o + d * middle, range, bounds_of);
            if (side == Side::Inside || (side == Side::Unknown && value(middle) < 0)) {
                visit(Crossing{0.5 * (t0 + middle), true, t0, middle});
                return;
            }
        }
    }
    // g's sign at the end of the last cell's stretch (its value, when taken, is among the recent values). It is the
    // sign where the next stretch starts, whether the run goes on or the line first crosses cells without surface,
    // through which g keeps its sign; before the first stretch, the sign outside when the line enters the box
    // through a face.
    bool known_inside = false, sign_known = enters_box;
    // One shell cell's stretch [a, b].
    const auto search_cell = [&](double a, double b, const ShellCellBounds& cell) {
        const auto no_crossing = [&](bool inside) {
            known_inside = inside, sign_known = true;
            return true;
        };
        // A stretch whose bound excludes zero holds no crossing: settled without its end values (most cells a line
        // crosses, before anything else of the cell is asked).
        ++work.search.interval_bounds;
        const Interval whole = cell.known ? cell.range(o + d * a, o + d * b) : ray.bound(a, b);
        if (whole.lo >= 0 || whole.hi < 0) return no_crossing(whole.hi < 0);
        const Interval cell_slope = cell.known ? cell.slope(d) : Interval::unbounded();
        // Bounds over a part [u, v] of the cell's stretch: the cell's first (a few products), the walk through
        // the deformations only where they settle nothing. Where both ends' values are known, the cell's bound of
        // g′ with them (a mean-value test) often settles what its bound of g does not.
        const auto bound = [&](double u, double v) {
            if (cell.known) {
                const Interval g = cell.range(o + d * u, o + d * v);
                if (g.lo >= 0 || g.hi < 0) return g;
                const double *g_u = values.find(u), *g_v = values.find(v);
                if (g_u && g_v && (*g_u < 0) == (*g_v < 0) &&
                    crossing_search_detail::keeps_sign(v - u, *g_u, *g_v, cell_slope))
                    return of_sign(*g_u < 0);
            }
            return ray.bound(u, v);
        };
        const auto slope = [&](double u, double v) {
            if (cell_slope.excludes_zero()) return cell_slope;
            const Interval walked = ray.slope_bound(u, v);
            const Interval both{std::max(walked.lo, cell_slope.lo), std::min(walked.hi, cell_slope.hi)};
            return both.lo <= both.hi ? both : walked;
        };
        // The stretches before told a's sign, perhaps without its value.
        const bool inside_a = sign_known ? known_inside : value(a) < 0;
        // g monotone over the cell and moving away from zero from a: no crossing, and b keeps a's sign.
        if ((cell_slope.lo > 0 && !inside_a) || (cell_slope.hi < 0 && inside_a)) {
            ++work.search.slope_proofs;
            return no_crossing(inside_a);
        }
        const double g_b = value(b);
        known_inside = g_b < 0, sign_known = true;
        // An occlusion query takes the first stretch whose ends differ in sign as it is (as the search would): its
        // start's value is not needed.
        if constexpr (precision == CrossingPrecision::SignChange)
            if (inside_a != (g_b < 0)) return visit(Crossing{0.5 * (a + b), g_b < 0, a, b});
        const double g_a = value(a);
        if (cell_slope.excludes_zero() && (g_a < 0) == (g_b < 0)) return true;  // monotone without a sign change
        return search_crossings<precision>(a, b, g_a, g_b, resolution, false, value, bound, slope, work.search, visit,
                                           value_and_slope);
    };
    shell_.visit_runs(o, d, t0, t1, range, bounds_of, [&](const SurfaceShell::Run& run) {
        // An occlusion query takes a run that leads from one sign to the other as a whole, as it takes a stretch
        // whose ends differ in sign: no value of g is needed (a ray through another object, as a rule).
        if constexpr (precision == CrossingPrecision::SignChange) {
            const Side before = run.before != Side::Unknown ? run.before
                                : sign_known                 ? (known_inside ? Side::Inside : Side::Outside)
                                                             : Side::Unknown;
            if (before != Side::Unknown && run.after != Side::Unknown && before != run.after)
                return visit(Crossing{0.5 * (run.lo() + run.hi()), run.after == Side::Inside, run.lo(), run.hi()});
        }
        for (std::size_t k = 0; k < run.size(); ++k)
            if (!search_cell(run.start(k), run.end(k), run.bounds(k))) return false;
        return true;
    });
}

std::optional<Crossing> Superquadric::first_of_crossings(const Vec3d& origin, const Vec3d& direction, double t_min,
                                                         double t_max, SuperquadricWork& work) const {
    std::optional<Crossing> first;
    search<CrossingPrecision::Refined>(origin, direction, t_min, t_max, true, work, [&](const Crossing& c) {
        first = c;
        return false;
    });
    return first;
}

std::optional<double> Superquadric::first_crossing(const Vec3d& origin, const Vec3d& direction, double t_min,
                                                   double t_max, SuperquadricWork& work) const {
    const std::optional<Crossing> first = first_of_crossings(origin, direction, t_min, t_max, work);
    return first ? std::optional<double>(first->t) : std::nullopt;
}

bool Superquadric::blocks(const Vec3d& origin, const Vec3d& direction, double t_min, float t_max,
                          SuperquadricWork& work) const {
    bool blocked = false, undecided = false;
    const auto settle = [&](const Crossing& c) {
        undecided = !c.settles_occlusion(t_min, t_max);
        blocked = !undecided;
        return false;
    };
    search<CrossingPrecision::SignChange>(origin, direction, t_min, t_max, true, work, settle);
    // A stretch from t_min itself (a ray that meets the object it leaves again) settles nothing as it is: its
    // crossing is isolated first, and refined only if that does not settle it either.
    if (undecided) search<CrossingPrecision::Bracketed>(origin, direction, t_min, t_max, true, work, settle);
    if (!undecided) return blocked;
    const std::optional<double> t = first_crossing(origin, direction, t_min, t_max, work);
    return t && *t > t_min && float(*t) < t_max;
}

bool Superquadric::inside_after_entry(const Vec3d& origin, const Vec3d& direction, double t, double past) const {
    // How far below zero g must be at past: far beyond its rounding, so that the surface really lies beyond.
    constexpr double kDepth = 1e-12;
    const SuperquadricAlongRay ray(*this, origin, direction);
    if (!(ray.value(past) < -kDepth)) return false;
    return (deformation_.empty() && shape_.is_convex()) || ray.slope_bound(t, past).hi < 0;
}

void Superquadric::crossings(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                             std::vector<Crossing>& out, SuperquadricWork& work) const {
    search<CrossingPrecision::Refined>(origin, direction, t_min, t_max, false, work, [&](const Crossing& c) {
        out.push_back(c);
        return true;
    });
}

}  // namespace isotrace
