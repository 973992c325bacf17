// The "abm_patch" shape: one attribute-based multi-sided patch or a model of patches sharing boundary curves,
// tessellated (patch_tessellation.h) and traced by Embree as triangles; or, with "draw": "curves", the boundary
// curves as thin tubes.
#include <algorithm>
#include <map>
#include <set>

#include "geometry/abm_patch/abm_patch.h"
#include "geometry/abm_patch/boundary_tubes.h"
#include "geometry/abm_patch/curve_sharing.h"
#include "geometry/abm_patch/patch_tessellation.h"
#include "geometry/abm_patch/smooth_joins.h"
#include "geometry/mesh/triangle_mesh_shape.h"
#include "renderer/core/memory_budget.h"
#include "renderer/params/world_limit.h"

namespace isotrace {
namespace {

using NamedCurves = std::map<std::string, std::shared_ptr<const SpaceCurve>>;

std::vector<Vec3d> control_points(const SceneNode& node) {
    const std::optional<SceneNode> list = node.optional_value("points");
    if (!list || !list->json().is_array()) node.fail("a curve needs \"points\": [[x, y, z], ...]");
    std::vector<Vec3d> points;
    for (const SceneNode& p : list->elements()) {
        points.push_back(p.as_vec3());
        // Farther out, the patch's weighted sums overflow, and Embree silently drops such bounds.
        if (!within_world(points.back())) p.fail(beyond_world_problem("control point"));
    }
    return points;
}

KnotVector knots_of(const SceneNode& node, int control_count) {
    const int degree = node.integer_or("degree", std::min(3, control_count - 1), NumberRange::between(1, KnotVector::kMaxDegree));
    if (control_count <= degree) node.fail("a degree-" + std::to_string(degree) + " curve needs at least " +
                                           std::to_string(degree + 1) + " points");
    const std::optional<SceneNode> knots = node.optional_value("knots");
    if (!knots || (knots->json().is_string() && knots->json().string == "clamped"))
        return KnotVector::clamped_uniform(degree, control_count);
    if (knots->json().is_string() && knots->json().string == "uniform") return KnotVector::uniform(degree, control_count);
    if (!knots->json().is_array()) knots->fail("expected \"clamped\", \"uniform\" or a list of knots");
    std::vector<double> values;
    for (const SceneNode& k : knots->elements()) values.push_back(k.as_number());
    if (values.size() != std::size_t(control_count + degree + 1))
        knots->fail(std::to_string(control_count) + " points of degree " + std::to_string(degree) + " need " +
                    std::to_string(control_count + degree + 1) + " knots, got " + std::to_string(values.size()));
    return at_node(*knots, [&] { return KnotVector(degree, std::move(values)); });
}

// {"type": "bezier" | "bspline" | "nurbs", "points": [...], "degree", "knots", "weights"}.
std::shared_ptr<const SpaceCurve> parse_curve(const SceneNode& node) {
    if (!node.json().is_object()) node.fail("expected a curve object, a curve name or {\"curve\": name, \"reversed\": true}");
    const std::string type = node.choice_or("type", "bezier", {"bezier", "bspline", "nurbs"});
    std::vector<Vec3d> points = control_points(node);
    std::shared_ptr<const SpaceCurve> curve;
    if (type == "bezier") {
        curve = at_node(node, [&] { return std::make_shared<const SpaceCurve>(SpaceCurve::bezier(std::move(points))); });
    } else {
        if (points.size() < 2) node.fail("a curve needs at least two points");
        const KnotVector knots = knots_of(node, int(points.size()));
        std::vector<double> weights;
        if (type == "nurbs") {
            const std::optional<SceneNode> list = node.optional_value("weights");
            if (!list || !list->json().is_array()) node.fail("a NURBS curve needs \"weights\" (one per point)");
            for (const SceneNode& w : list->elements()) weights.push_back(w.as_number(NumberRange::positive()));
        }
        curve = at_node(node, [&] { return std::make_shared<const SpaceCurve>(knots, std::move(points), weights); });
    }
    node.finish();
    return curve;
}

PatchSide parse_side(const SceneNode& node, const NamedCurves& named, const std::string& fallback_name) {
    auto lookup = [&](const SceneNode& name_node, const std::string& name) {
        const auto found = named.find(name);
        if (found == named.end()) {
            std::string known;
            for (const auto& [n, c] : named) known += (known.empty() ? "" : ", ") + n;
            name_node.fail("no curve named \"" + name + "\" in \"curves\"" + (known.empty() ? "" : "; curves: " + known));
        }
        return found->second;
    };
    if (node.json().is_string()) return {lookup(node, node.json().string), false, "curve \"" + node.json().string + "\"", nullptr};
    if (node.json().is_object() && node.has("curve")) {
        const std::string name = node.string("curve");
        const bool reversed = node.boolean_or("reversed", false);
        node.finish();
        return {lookup(node, name), reversed, "curve \"" + name + "\"" + (reversed ? " (reversed)" : ""), nullptr};
    }
    return {parse_curve(node), false, fallback_name, nullptr};
}

std::shared_ptr<const PatchDomain> domain_for(const SceneNode& patch, int sides) {
    const std::string kind = patch.choice_or("domain", "auto", {"auto", "triangle", "square", "polygon"});
    if ((kind == "triangle" && sides != 3) || (kind == "square" && sides != 4))
        patch.fail_at("domain", "the " + kind + " domain needs " + (kind == "triangle" ? "3" : "4") + " curves, the patch has " +
                                    std::to_string(sides));
    if (kind == "triangle" || (kind == "auto" && sides == 3)) return right_triangle_domain();
    if (kind == "square" || (kind == "auto" && sides == 4)) return unit_square_domain();
    return at_node(patch, [&] { return std::shared_ptr<const PatchDomain>(regular_polygon_domain(sides)); });
}

// `smooth`: the shape's joins are smooth, which need p > 1 (and make 2 the default).
AbmPatch parse_patch(const SceneNode& patch, const NamedCurves& named, double closure_tolerance, bool smooth) {
    const std::optional<SceneNode> boundary = patch.optional_value("boundary");
    if (!boundary || !boundary->json().is_array()) patch.fail("a patch needs \"boundary\": a list of 3 to 8 curves");
    const std::vector<SceneNode> items = boundary->elements();
    if (items.size() < 3 || items.size() > std::size_t(PatchDomain::kMaxSides))
        boundary->fail("a patch needs 3 to " + std::to_string(PatchDomain::kMaxSides) + " boundary curves, got " +
                       std::to_string(items.size()));
    std::vector<PatchSide> sides;
    for (std::size_t i = 0; i < items.size(); ++i) sides.push_back(parse_side(items[i], named, "curve " + std::to_string(i)));
    const double p = patch.number_or("p", smooth ? 2 : 1, NumberRange::between(AbmPatch::kMinExponent, AbmPatch::kMaxExponent));
    if (smooth && !(p > 1))
        patch.fail_at("p", "smooth joins need p > 1: with p = 1 the other curves pull the surface off the shared "
                           "tangent plane");
    const std::shared_ptr<const PatchDomain> domain = domain_for(patch, int(sides.size()));
    return at_node(*boundary, [&] { return AbmPatch(domain, std::move(sides), p, closure_tolerance); });
}

std::unique_ptr<Shape> create(const SceneNode& node) {
    NamedCurves named;
    if (const std::optional<SceneNode> curves = node.optional_value("curves")) {
        if (!curves->json().is_object()) curves->fail("expected an object of named curves");
        for (const std::string& name : curves->keys()) named[name] = parse_curve(curves->object(name));
    }
    const double closure_tolerance = node.number_or("closure_tolerance", 1e-6, NumberRange::positive());
    const bool smooth = node.choice_or("joins", "crease", {"crease", "smooth"}) == "smooth";
    std::vector<AbmPatch> patches;
    if (node.has("patches") == node.has("boundary")) node.fail("give one patch (\"boundary\") or a list (\"patches\")");
    if (node.has("boundary")) {
        patches.push_back(parse_patch(node, named, closure_tolerance, smooth));
    } else {
        const std::vector<SceneNode> list = node.object_array("patches");
        if (list.empty()) node.fail_at("patches", "needs at least one patch");
        for (const SceneNode& patch : list) {
            patches.push_back(parse_patch(patch, named, closure_tolerance, smooth));
            patch.finish();
        }
        try {
            patches = share_coincident_curves(patches, closure_tolerance);
        } catch (const NearlySharedCurve& near) {
            list[near.patch].optional_value("boundary")->elements()[near.side].fail(near.what());
        }
        if (smooth) patches = at_node(node, [&] { return with_smooth_joins(patches); });
    }
    const std::string draw = node.choice_or("draw", "surface", {"surface", "curves"});
    const SourceLocation where = node.location();
    TriangleMeshData mesh;
    if (draw == "curves") {
        std::vector<const SpaceCurve*> curves;
        std::set<const SpaceCurve*> listed;
        for (const AbmPatch& patch : patches)
            for (const PatchSide& side : patch.sides())
                if (listed.insert(side.curve.get()).second) curves.push_back(side.curve.get());
        const double radius = node.number_or("tube_radius", 0.01, NumberRange::positive());
        const std::uint64_t triangles = saturating_product({curves.size(), kBoundaryTube.triangle_count()});
        node.context().memory->charge(saturating_product({triangles, kSweepTubeTrianglePeakBytes}),
                                      "tubes of " + std::to_string(curves.size()) + " curves", where, node.path());
        mesh = at_node(node, [&] { return boundary_tubes(curves, radius); });
    } else {
        PatchTessellationOptions options;
        options.tolerance = node.number_or("tolerance", options.tolerance, NumberRange::positive());
        options.max_segments = node.integer_or("max_segments", options.max_segments, NumberRange::between(1, 4096));
        options.segments = node.integer_or("segments", 0, NumberRange::between(0, 4096));
        std::uint64_t charged = 0;
        options.before_building = [&](std::uint64_t triangles) {
            const std::uint64_t bytes = saturating_product({triangles, kPatchTrianglePeakBytes});
            if (bytes > charged)
                node.context().memory->charge(bytes - charged, "a tessellation of " + std::to_string(triangles) + " triangles",
                                              where, node.path());
            charged = std::max(charged, bytes);
        };
        mesh = at_node(node, [&] { return tessellate_patches(patches, options); });
    }
    for (const Vec3f& p : mesh.positions)
        if (!is_finite(p)) node.fail("the patch reaches beyond float range");
    mesh.remove_degenerate_triangles();
    if (mesh.triangles.empty()) node.fail("the patches have no triangles of non-zero area");
    return std::make_unique<TriangleMeshShape>(std::move(mesh));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "abm_patch",
                         "attribute-based multi-sided patches (3 to 8 boundary curves each): boundary or patches, "
                         "curves (named), p, domain, joins (crease/smooth), closure_tolerance, tolerance, max_segments, segments, draw (surface/curves), "
                         "tube_radius",
                         create)

}  // namespace isotrace
