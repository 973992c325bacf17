#pragma once
// Polygonising an implicit field into a triangle mesh: marching cubes or dual contouring on the Cartesian
// octree's finest level, or dual contouring on a spherical octree (Kim et al. 2011, and the seed paper's stable
// construction). The octrees subdivide only cells that may hold surface (ImplicitField::may_reach_surface), down
// to bricks of 8³ finest cells that are sampled whole (lattice_samples.h), so every cell the surface cuts is found
// at the finest level; empty space stays coarse and produces nothing. Cartesian dual
// contouring may then simplify the octree by QEF error (octree_simplification.h). Both octrees span the box of
// the surface (surface_bounds.h), not the field's bounds(): the depth is a cell size relative to the surface.
#include <cstddef>
#include <optional>
#include <string>

#include "geometry/mesh/triangle_mesh_data.h"
#include "geometry/polygonize/dual_contouring.h"
#include "geometry/polygonize/mesh_topology.h"
#include "geometry/polygonize/octree_simplification.h"
#include "geometry/polygonize/spherical_lattice.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

enum class PolygonizeMethod { MarchingCubes, DualContouring, SphericalDualContouring };

struct PolygonizeOptions {
    PolygonizeMethod method = PolygonizeMethod::DualContouring;
    int depth = 6;                 // 2^depth cells along each lattice axis
    // Spherical only (given for another method, they are errors):
    std::optional<Vec3d> origin;       // the lattice's origin (default: the centre of the surface's bounds)
    bool correct_origin = true;        // move the origin off the surface first (spherical_origin.h)
    std::optional<PoleCap> pole_cap;   // default: PoleCap::AxisRoot
    // dc only: collapse octree nodes whose vertex lies within this distance (scene units) of every tangent plane
    // in the node, where the topology allows (octree_simplification.h).
    std::optional<double> simplify;
};

struct PolygonizeReport {
    FieldBox bounds;                  // the surface's, which the lattice spans (surface_bounds.h)
    std::size_t candidate_cells = 0;  // finest cells of the bricks the octree kept (lattice_samples.h)
    std::size_t surface_cells = 0;    // those with corners of both signs
    std::size_t corner_samples = 0;   // field values taken at their corners
    std::size_t cut_edges = 0;
    DualContouringStatistics dual;
    SimplificationStatistics simplification;
    EdgeUse edges;  // boundary and over-shared edges of the mesh: both 0 unless correct_origin was off
    // Spherical only.
    Vec3d requested_origin;
    SphericalRange range;
    int origin_steps = 0;
    bool origin_clear = false;  // origin correction ended two cells clear of the surface (spherical_origin.h)
};

struct Polygonization {
    TriangleMeshData mesh;  // normals: the field's gradient direction at each vertex
    PolygonizeReport report;
};

// The depths each method accepts.
int min_depth(PolygonizeMethod method);
constexpr int kMaxPolygonizeDepth = 10;

// The "mc", "dc", "sdc" names of the methods (for the command line and scene files); std::nullopt for others.
std::optional<PolygonizeMethod> polygonize_method_named(const std::string& name);
std::optional<PoleCap> pole_cap_named(const std::string& name);  // "axis", "normal", "vertical"

// Throws std::invalid_argument naming the setting at fault ("depth: ...", "origin: ...", "pole_cap: ...",
// "correct_origin: ...", "simplify: ...") for a depth out of range (with the memory it would need), an origin that is not finite or lies
// outside the surface's bounds (surface_bounds.h), spherical settings given for a Cartesian method, a simplification tolerance that is
// negative or not finite or given for another method than dc, or a field whose bounds are empty; and, naming no
// setting, when it cannot make a closed mesh: an origin that origin correction cannot move off the surface (the
// field is flat all round it), or a mesh with boundary or over-shared edges. With correct_origin off, a mesh with
// holes is returned (for comparison) and its edges are counted in the report.
Polygonization polygonize_field(const ImplicitField& field, const PolygonizeOptions& options);

}  // namespace isotrace
