#include "geometry/mesh/triangle_mesh_shape.h"

#include <algorithm>
#include <cstring>
#include <sstream>
#include <string>
#include <utility>

#include "geometry/csg/inside_span_list.h"
#include "geometry/mesh/mesh_closedness.h"
#include "geometry/mesh/mesh_deformer.h"
#include "geometry/mesh/mesh_file.h"
#include "geometry/mesh/mesh_inside_spans.h"
#include "renderer/math/line_box_clip.h"
#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

// The buffers of an inside-span query: the line's crossings with the surface, and the spans before clipping.
struct SpanBuffers {
    std::vector<MeshCrossing> crossings;
    std::vector<InsideSpan> unclipped;
};

}  // namespace

TriangleMeshShape::TriangleMeshShape(TriangleMeshData mesh) : mesh_(std::move(mesh)) { build_area_distribution(); }

void TriangleMeshShape::build_area_distribution() {
    std::vector<double> areas;
    areas.reserve(mesh_.triangles.size());
    for (const auto& triangle : mesh_.triangles) {
        const Vec3d p0(mesh_.positions[triangle[0]]);
        const Vec3d p1(mesh_.positions[triangle[1]]);
        const Vec3d p2(mesh_.positions[triangle[2]]);
        areas.push_back(0.5 * length(cross(p1 - p0, p2 - p0)));
    }
    areas_ = AreaDistribution(areas);
}

SurfaceSample TriangleMeshShape::sample_surface(std::array<float, 2> u) const {
    if (!(areas_.total() > 0)) return {};
    const AreaDistribution::Pick pick = areas_.pick(u[0]);
    const auto [b0, b1] = square_to_uniform_triangle({pick.reused_u, u[1]});
    const auto& triangle = mesh_.triangles[pick.index];
    const Vec3f& p0 = mesh_.positions[triangle[0]];
    const Vec3f& p1 = mesh_.positions[triangle[1]];
    const Vec3f& p2 = mesh_.positions[triangle[2]];
    SurfaceSample sample;
    sample.position = p0 * b0 + p1 * b1 + p2 * (1 - b0 - b1);
    // (v1-v0)x(v2-v0): Embree's Ng, the counter-clockwise front that shading() reports.
    sample.normal = Vec3f(normalize(cross(Vec3d(p1) - Vec3d(p0), Vec3d(p2) - Vec3d(p0))));
    sample.pdf_area = float(1.0 / areas_.total());
    return sample;
}

Bounds3f TriangleMeshShape::bounds() const {
    Bounds3f b;
    for (const Vec3f& p : mesh_.positions) b.extend(p);
    return b;
}

void TriangleMeshShape::bake(const Transform& to_world) {
    mesh_.transform(to_world);
    // Normals and uvs belong to vertices and follow a mirroring transform's swapped corners; only the barycentric
    // fallback uv needs to know (see shading()).
    if (to_world.determinant() < 0) winding_swapped_ = !winding_swapped_;
    build_area_distribution();
}

RTCGeometry TriangleMeshShape::create_geometry(RTCDevice device) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree-owned buffers: they come padded for its 16-byte vector loads.
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh_.positions.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), mesh_.triangles.size()));
    if (!vertices || !indices) return geometry;  // the caller reports Embree's error
    for (std::size_t i = 0; i < mesh_.positions.size(); ++i) {
        vertices[3 * i] = mesh_.positions[i].x;
        vertices[3 * i + 1] = mesh_.positions[i].y;
        vertices[3 * i + 2] = mesh_.positions[i].z;
    }
    static_assert(sizeof(mesh_.triangles[0]) == 3 * sizeof(unsigned));
    std::memcpy(indices, mesh_.triangles.data(), mesh_.triangles.size() * sizeof(mesh_.triangles[0]));
    rtcCommitGeometry(geometry);
    return geometry;
}

std::string TriangleMeshShape::solid_problem() const {
    const std::string problem = closed_mesh_problem(mesh_);
    return problem.empty() ? problem : type_name() + " " + problem;
}

void TriangleMeshShape::prepare_span_queries(RTCDevice device) {
    crossing_scene_ = std::make_unique<MeshCrossingScene>(device, create_geometry(device));
    span_bounds_ = bounds();
    // Enlarged so that a line in a face of the bounding box still counts as passing through it.
    const Vec3f margin = (span_bounds_.upper - span_bounds_.lower) * 1e-4f + Vec3f(1e-30f, 1e-30f, 1e-30f);
    span_bounds_.lower -= margin;
    span_bounds_.upper += margin;
}

void TriangleMeshShape::inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                                     std::vector<InsideSpan>& spans, QueryScratch& scratch) const {
    const auto range = clip_line_to_box(Vec3d(span_bounds_.lower), Vec3d(span_bounds_.upper), origin, direction,
                                        -INFINITY, INFINITY);
    if (!range || !(range->t_enter < range->t_exit) || range->t_exit < t_min || range->t_enter > t_max) return;
    // The query starts where the line enters the bounds (outside the mesh), so crossing directions alone tell
    // inside from outside, also for rays that start inside.
    const double start = range->t_enter, end = range->t_exit;
    const QueryScratch::Level level(scratch);
    auto& [crossings, unclipped] = level.get<SpanBuffers>();
    crossings.clear();
    unclipped.clear();
    crossing_scene_->crossings(origin + direction * start, direction, end - start, crossings);
    for (MeshCrossing& crossing : crossings) crossing.t += start;
    // Crossings closer than a millionth of the chord are one event (float precision of the query is ~1e-7).
    mesh_inside_spans(crossings, direction, 1e-6 * (end - start), unclipped);
    for (const InsideSpan& span : unclipped) append_clipped_span(span, t_min, t_max, spans);
}

LocalShading TriangleMeshShape::shading(const RTCHit& hit, const Vec3f& embree_normal, const Vec3d&) const {
    // Embree's Ng = (v1-v0)x(v2-v0): the counter-clockwise front. Its (u, v) are the barycentrics of the second and
    // third corners, of the original triangle's third and second after a mirroring bake reversed it.
    LocalShading result = shading_of_embree_hit(hit, embree_normal, winding_swapped_);
    const auto& triangle = mesh_.triangles[hit.primID];
    const float w = 1 - hit.u - hit.v;
    if (!mesh_.normals.empty()) {
        const Vec3f n = mesh_.normals[triangle[0]] * w + mesh_.normals[triangle[1]] * hit.u +
                        mesh_.normals[triangle[2]] * hit.v;
        const float len = length(n);
        if (len > 0 && std::isfinite(len)) result.normal = n / len;
    }
    if (!mesh_.uvs.empty()) {
        for (int k = 0; k < 2; ++k)
            result.uv[std::size_t(k)] = mesh_.uvs[triangle[0]][std::size_t(k)] * w +
                                        mesh_.uvs[triangle[1]][std::size_t(k)] * hit.u +
                                        mesh_.uvs[triangle[2]][std::size_t(k)] * hit.v;
        const UvDerivatives derivatives = uv_derivatives(triangle);
        result.dpdu = derivatives.dpdu;
        result.dpdv = derivatives.dpdv;
    }
    return result;
}

TriangleMeshShape::UvDerivatives TriangleMeshShape::uv_derivatives(const std::array<std::uint32_t, 3>& triangle) const {
    // p − p2 = (u − u2)·dpdu + (v − v2)·dpdv at the corners 0 and 1: a 2×2 system in the uv differences, solved in
    // double so that thin uv triangles keep their precision.
    const Vec3d p2(mesh_.positions[triangle[2]]);
    const Vec3d dp02 = Vec3d(mesh_.positions[triangle[0]]) - p2, dp12 = Vec3d(mesh_.positions[triangle[1]]) - p2;
    const auto& uv0 = mesh_.uvs[triangle[0]];
    const auto& uv1 = mesh_.uvs[triangle[1]];
    const auto& uv2 = mesh_.uvs[triangle[2]];
    const double du02 = double(uv0[0]) - uv2[0], dv02 = double(uv0[1]) - uv2[1];
    const double du12 = double(uv1[0]) - uv2[0], dv12 = double(uv1[1]) - uv2[1];
    const double determinant = du02 * dv12 - dv02 * du12;
    const Vec3f dpdu((dp02 * dv12 - dp12 * dv02) / determinant);
    const Vec3f dpdv((dp12 * du02 - dp02 * du12) / determinant);
    // Collinear uvs (a zero determinant) do not parametrise the triangle, nor do ones so nearly collinear that
    // the derivatives leave float range.
    if (!is_finite(dpdu) || !is_finite(dpdv)) return {};
    return {dpdu, dpdv};
}

HitShading TriangleMeshShape::hit_shading() const {
    if (!mesh_.normals.empty() || !mesh_.uvs.empty()) return HitShading::Computed;
    return winding_swapped_ ? HitShading::EmbreeHitSwappedUv : HitShading::EmbreeHit;
}

namespace {

std::string format_number(double v) {  // "3", "1.5", "-1" rather than std::to_string's "3.000000"
    std::ostringstream out;
    out << v;
    return out.str();
}

// Inline meshes: "positions": [[x,y,z], ...], "triangles": [[i,j,k], ...], optional "normals", "uvs".
TriangleMeshData parse_inline_mesh(const SceneNode& node) {
    TriangleMeshData mesh;
    const auto positions = node.optional_value("positions");
    if (!positions) node.fail("a mesh needs \"file\" or inline \"positions\" and \"triangles\"");
    for (const SceneNode& p : positions->elements()) mesh.positions.push_back(Vec3f(p.as_vec3()));
    if (auto normals = node.optional_value("normals"))
        for (const SceneNode& n : normals->elements()) mesh.normals.push_back(Vec3f(n.as_vec3()));
    if (auto uvs = node.optional_value("uvs"))
        for (const SceneNode& uv : uvs->elements()) {
            if (!uv.json().is_array() || uv.json().items.size() != 2) uv.fail("expected [u, v]");
            mesh.uvs.push_back({float(uv.elements()[0].as_number()), float(uv.elements()[1].as_number())});
        }
    const auto triangles = node.optional_value("triangles");
    if (!triangles) node.fail("an inline mesh needs \"triangles\"");
    for (const SceneNode& t : triangles->elements()) {
        const Vec3d index = t.as_vec3();
        std::array<std::uint32_t, 3> triangle{};
        for (int k = 0; k < 3; ++k) {
            if (index[k] < 0 || index[k] != std::floor(index[k]) || index[k] >= double(mesh.positions.size()))
                t.fail("vertex index " + format_number(index[k]) + " is not an index into positions (" +
                       std::to_string(mesh.positions.size()) + " vertices)");
            triangle[std::size_t(k)] = std::uint32_t(index[k]);
        }
        mesh.triangles.push_back(triangle);
    }
    try {
        mesh.validate(node.location().file);
    } catch (const InputError& error) {
        node.fail((error.field().empty() ? "" : error.field() + ": ") + error.problem());
    }
    return mesh;
}

// A problem inside the mesh file is reported with the scene line that names the file, then the file's own line.
TriangleMeshData load_referenced_file(const SceneNode& node) {
    const std::string path = node.file_path("file").string();
    try {
        return load_mesh_file(path, *node.context().memory);
    } catch (const InputError& error) {
        node.fail_at("file", error.what());
    }
}

std::unique_ptr<Shape> create(const SceneNode& node) {
    if (node.has("file") && node.has("positions")) node.fail("give either \"file\" or inline \"positions\", not both");
    TriangleMeshData mesh = node.has("file") ? load_referenced_file(node) : parse_inline_mesh(node);
    apply_mesh_deformers(node, mesh);
    mesh.remove_degenerate_triangles();
    if (mesh.triangles.empty()) node.fail("the mesh has no triangles of non-zero area");
    return std::make_unique<TriangleMeshShape>(std::move(mesh));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "mesh",
                         "triangle mesh; file (.obj/.ply/.bpt, relative to the scene) or inline positions, triangles, normals, uvs; "
                         "deformers",
                         create)

}  // namespace isotrace
