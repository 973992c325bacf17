#include "geometry/polygonize/polygonize_field.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "geometry/field/surface_bounds.h"
#include "geometry/polygonize/cartesian_lattice.h"
#include "geometry/polygonize/marching_cubes.h"
#include "geometry/polygonize/spherical_origin.h"

namespace isotrace {
namespace {

// A sphere filling the root cell crosses about 1.5·π·4^L finest cells; each costs roughly this much memory while
// polygonising (keys, eight corner samples, Hermite data, vertices, triangles).
constexpr double kBytesPerSurfaceCell = 400;

void check_depth(PolygonizeMethod method, int depth) {
    if (depth >= min_depth(method) && depth <= kMaxPolygonizeDepth) return;
    char message[256];
    const double cells = 1.5 * 3.14159 * std::pow(4.0, depth);
    std::snprintf(message, sizeof message,
                  "depth: %d is out of range %d..%d (a surface like a sphere needs about %.3g surface cells, %.3g GB, "
                  "at that depth)",
                  depth, min_depth(method), kMaxPolygonizeDepth, cells, cells * kBytesPerSurfaceCell / 1e9);
    throw std::invalid_argument(message);
}

void check_simplify(const PolygonizeOptions& options) {
    if (!options.simplify) return;
    if (options.method != PolygonizeMethod::DualContouring)
        throw std::invalid_argument("simplify: only dual contouring on the Cartesian octree (dc) can be simplified");
    if (!(*options.simplify >= 0) || !std::isfinite(*options.simplify))
        throw std::invalid_argument("simplify: the tolerance must be a finite distance >= 0");
}

std::string point_text(const Vec3d& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x, p.y, p.z);
    return text;
}

// Settings of the spherical lattice make no sense for the Cartesian one: refused rather than ignored.
void check_spherical_settings(const PolygonizeOptions& options) {
    if (options.method == PolygonizeMethod::SphericalDualContouring) {
        if (options.origin && !is_finite(*options.origin)) {
            const Vec3d& o = *options.origin;
            const bool nan = std::isnan(o.x) || std::isnan(o.y) || std::isnan(o.z);
            throw std::invalid_argument("origin: " + point_text(o) + " has a coordinate that is " +
                                        (nan ? "NaN (not a number)" : "infinite"));
        }
        return;
    }
    const char* const why = " applies only to spherical-octree dual contouring (sdc)";
    if (options.origin) throw std::invalid_argument(std::string("origin: an origin") + why);
    if (options.pole_cap) throw std::invalid_argument(std::string("pole_cap: the pole cap") + why);
    if (!options.correct_origin) throw std::invalid_argument(std::string("correct_origin: origin correction") + why);
}

void report_samples(const LatticeSamples& samples, PolygonizeReport& report) {
    report.candidate_cells = samples.candidate_cells;
    report.surface_cells = samples.cells.size();
    report.corner_samples = samples.corner_samples;
    report.cut_edges = samples.edges.size();
}

Polygonization mesh_of(const ImplicitField& field, const FieldBox& bounds, const PolygonizeOptions& options) {
    Polygonization result;
    PolygonizeReport& report = result.report;
    if (options.method != PolygonizeMethod::SphericalDualContouring) {
        const CartesianLattice lattice = CartesianLattice::around(bounds, options.depth);
        const LatticeSamples samples = sample_lattice(field, lattice);
        report_samples(samples, report);
        if (options.method == PolygonizeMethod::MarchingCubes) {
            result.mesh = marching_cubes(samples, lattice, field);
            return result;
        }
        DualVertices vertices = cell_vertices(samples, lattice);
        if (options.simplify)
            report.simplification = simplify_octree(samples, lattice, field, *options.simplify, vertices);
        result.mesh = dual_contour(samples, lattice, field, vertices, PoleCap::AxisRoot, report.dual);
        return result;
    }
    report.requested_origin = options.origin.value_or(bounds.centre());
    if (!bounds.contains(report.requested_origin))
        throw std::invalid_argument("origin: " + point_text(report.requested_origin) +
                                    " lies outside the surface's bounds " + point_text(bounds.lower) + " to " +
                                    point_text(bounds.upper));
    Vec3d origin = report.requested_origin;
    std::optional<OriginCorrection> correction;
    if (options.correct_origin) {
        correction = correct_origin(field, origin, options.depth);
        origin = correction->origin;
        report.origin_steps = correction->steps;
        report.origin_clear = correction->converged;
    }
    report.range = spherical_range(field, origin);
    // An origin short of two cells' clearance still serves while no surface comes within r_min; one that found no
    // room at all (r_min at its floor) would leave a hole around it.
    if (correction && !correction->converged && report.range.r_min <= kMinRadiusFraction * report.range.r_max)
        throw std::invalid_argument("origin: " + point_text(report.requested_origin) +
                                    " could not be moved clear of the surface (stopped after " +
                                    std::to_string(correction->steps) + " steps at " + point_text(origin) +
                                    ", where the field is flat or the surface is still near); give another origin");
    const SphericalLattice lattice(report.range, options.depth);
    const LatticeSamples samples = sample_lattice(field, lattice);
    report_samples(samples, report);
    result.mesh = dual_contour(samples, lattice, field, cell_vertices(samples, lattice),
                               options.pole_cap.value_or(PoleCap::AxisRoot), report.dual);
    return result;
}

}  // namespace

int min_depth(PolygonizeMethod method) { return method == PolygonizeMethod::SphericalDualContouring ? 2 : 1; }

std::optional<PolygonizeMethod> polygonize_method_named(const std::string& name) {
    if (name == "mc") return PolygonizeMethod::MarchingCubes;
    if (name == "dc") return PolygonizeMethod::DualContouring;
    if (name == "sdc") return PolygonizeMethod::SphericalDualContouring;
    return std::nullopt;
}

std::optional<PoleCap> pole_cap_named(const std::string& name) {
    if (name == "axis") return PoleCap::AxisRoot;
    if (name == "normal") return PoleCap::NormalProjection;
    if (name == "vertical") return PoleCap::VerticalProjection;
    return std::nullopt;
}

Polygonization polygonize_field(const ImplicitField& field, const PolygonizeOptions& options) {
    check_depth(options.method, options.depth);
    check_simplify(options);
    check_spherical_settings(options);
    // The lattices span the surface, not what the field's bounds promise (surface_bounds.h).
    const SurfaceBoundedField bounded(field);
    const FieldBox bounds = bounded.bounds();
    if (!is_finite(bounds.lower) || !is_finite(bounds.upper) || !(max_component(bounds.extent()) > 0))
        throw std::invalid_argument("the surface is empty (its bounds have no extent)");
    Polygonization result = mesh_of(bounded, bounds, options);
    result.report.bounds = bounds;
    // A closed surface inside the bounds must give a closed mesh; anything else is a failure, not a result
    // (unless origin correction was turned off to show what it prevents).
    result.report.edges = edge_use(result.mesh);
    const EdgeUse& edges = result.report.edges;
    if ((edges.boundary || edges.over_shared) && options.correct_origin)
        throw std::invalid_argument("the mesh would have " + std::to_string(edges.boundary) + " boundary and " +
                                    std::to_string(edges.over_shared) +
                                    " over-shared edges (a closed surface must give a closed mesh); try another "
                                    "depth or method");
    return result;
}

}  // namespace isotrace
