// The "sweep" and "sweep_hierarchy" mesh deformers (docs/scene-format.md, "Sweep deformers").

#include <algorithm>
#include <array>
#include <sstream>

#include "geometry/curves/curve_interpolation.h"
#include "geometry/sweep/sweep_assignment.h"
#include "geometry/sweep/sweep_coverage.h"
#include "geometry/sweep/sweep_deformer.h"
#include "geometry/sweep/sweep_family_deformer.h"
#include "geometry/sweep/sweep_hierarchy.h"
#include "geometry/sweep/sweep_spec.h"
#include "geometry/sweep/sweep_surface.h"
#include "geometry/sweep/sweep_tessellation.h"
#include "geometry/sweep/vertex_group.h"
#include "renderer/core/memory_budget.h"
#include "renderer/core/parallel_for.h"

namespace isotrace {
namespace {

// Wall seconds since `start`: the summaries report binding and deformation times (the sweep benchmark).
double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}


// Refining a bound vertex's roots and placing it takes about as long as this many samples (measured).
constexpr std::uint64_t kBindingStepsPerVertex = 150;
// What binding holds per sample of t: the parameter, the centre and the normal there.
constexpr std::uint64_t kBinderBytesPerSample = sizeof(double) + 2 * sizeof(Vec3d);
// A vertex's neighbours (about six, in a vector) and its node in the map of positions (vertex_neighbours).
constexpr std::uint64_t kNeighbourBytesPerVertex = sizeof(std::vector<std::uint32_t>) + 6 * sizeof(std::uint32_t) + 64;
// What a sweep deformer holds per vertex: the positions in double and its copy of them, the bindings, weights,
// moved positions and uvs, and the neighbours for the coverage check.
constexpr std::uint64_t kSweepBytesPerVertex = 3 * sizeof(Vec3d) + sizeof(std::optional<VertexBinding>) + sizeof(double) +
                                               sizeof(std::array<float, 2>) + kNeighbourBytesPerVertex;
// A hierarchy's: the positions in double, each vertex's sweep and group, its distance and neighbours while sweeps
// are assigned; per sweep, its binding.
constexpr std::uint64_t kHierarchyBytesPerVertex = sizeof(Vec3d) + 2 * sizeof(int) + sizeof(double) + kNeighbourBytesPerVertex;
constexpr std::uint64_t kHierarchyBytesPerBinding = sizeof(std::optional<VertexBinding>);
// Keeping a child's volume ratio rebuilds it once per secant step, at most this many times.
constexpr std::uint64_t kVolumeRebuilds = 42;

// Key sections and radii beyond what a sweep takes are refused when it is built; the estimate stops there.
std::uint64_t capped(std::size_t count) { return std::min<std::uint64_t>(count, kMaxInterpolatedPoints); }

std::uint64_t construction_steps(const SweepSpec& sweep, std::uint64_t keys) {
    return SweepSurface::construction_steps(keys, capped(sweep.radius_count()));
}

// Radii measured on the mesh trace a copy of it (RadiusProbe): as much memory per triangle as a traced tube.
std::uint64_t probe_bytes(const SweepSpec& sweep, const TriangleMeshData& mesh) {
    return sweep.measures_radii() ? saturating_product({mesh.triangles.size(), kSweepTubeTrianglePeakBytes}) : 0;
}

// The mean of a sweep's key radii: the scale of the band over which two sweeps' vertices are blended.
double mean_radius(const SweepSurface& sweep) {
    double sum = 0;
    std::size_t count = 0;
    for (const KeySection& key : sweep.keys())
        for (double r : key.radii) {
            sum += r;
            ++count;
        }
    return sum / double(count);
}

std::vector<Vec3d> positions_of(const TriangleMeshData& mesh) {
    std::vector<Vec3d> points;
    for (const Vec3f& p : mesh.positions) points.emplace_back(p);
    return points;
}

class SingleSweepDeformer final : public SweepFamilyDeformer {
public:
    explicit SingleSweepDeformer(const SceneNode& node)
        : sweep_(parse_sweep_spec(node)),
          local_(node.choice_or("mode", "local", {"local", "global"}) == "local"),
          levels_(node.integer_or("levels", 1, NumberRange::between(1, MultiResolutionSweep::kMaxLevels))),
          weights_as_uv_(node.boolean_or("weights_as_uv", false)) {
        if (const auto curve = node.optional_value("weight_curve")) {
            std::vector<double> values;
            for (const SceneNode& v : curve->elements()) values.push_back(v.as_number());
            weight_ = at_node(*curve, [&] { return WeightCurve(values); });
        }
        for (const SceneNode& edit : node.object_array("edits")) edits_.push_back(parse_edit_spec(edit, false));
    }

    Cost cost(const TriangleMeshData& mesh) const override {
        const std::uint64_t levels = std::uint64_t(levels_), vertices = mesh.positions.size();
        const std::uint64_t keys = capped(((sweep_.keys.size() - 1) << (levels_ - 1)) + 1);  // the finest level's
        const std::uint64_t samples = SweepBinder::sample_count(keys);
        // Each level's sweep is built from the coarser ones: for the levels, the binding, each edit and the result.
        const std::uint64_t constructions = levels * (levels + edits_.size() + 3);
        return {saturating_sum({saturating_product({vertices, samples + kBindingStepsPerVertex}),
                                saturating_product({constructions, construction_steps(sweep_, keys)})}),
                saturating_sum({saturating_product({vertices, kSweepBytesPerVertex}), samples * kBinderBytesPerSample,
                                probe_bytes(sweep_, mesh)})};
    }

    std::vector<SweepSurface> sweeps(const TriangleMeshData& mesh, bool edited) const override {
        MultiResolutionSweep sweep = initial(mesh);
        if (edited) edit(sweep);
        return {sweep.finest()};
    }

    std::string apply(TriangleMeshData& mesh) const override {
        MultiResolutionSweep sweep = initial(mesh);
        const auto binding_start = std::chrono::steady_clock::now();
        const SweepDeformer deformer(sweep.finest(), positions_of(mesh),
                                     local_ ? SweepDeformer::Mode::local : SweepDeformer::Mode::global, weight_);
        const double binding_seconds = seconds_since(binding_start);
        const auto deformation_start = std::chrono::steady_clock::now();
        edit(sweep);
        const std::vector<Vec3d> moved = at_node(sweep_.node, [&] { return deformer.deform(sweep.finest()); });
        for (std::size_t i = 0; i < moved.size(); ++i) mesh.positions[i] = Vec3f(moved[i]);
        const double deformation_seconds = seconds_since(deformation_start);
        if (weights_as_uv_) {  // to show the weights through a texture (the paper's Fig. 5)
            mesh.uvs.clear();
            // u kept off the texture's edges, where a repeating lookup would blend its two ends.
            for (double w : deformer.weights()) mesh.uvs.push_back({float(0.005 + 0.99 * w), 0.5f});
        }
        const BindingStatistics& s = deformer.statistics();
        std::ostringstream summary;
        summary << "sweep" << (sweep_.name.empty() ? "" : " \"" + sweep_.name + "\"") << " (" << (local_ ? "local" : "global")
                << ", " << levels_ << " level" << (levels_ > 1 ? "s" : "") << "): " << s.points << " vertices, " << s.bound
                << " bound (" << s.inside << " inside the sweep, " << s.weighted << " moved), " << s.unbound() << " unbound"
                << "; binding " << binding_seconds << " s, deformation " << deformation_seconds << " s";
        const SweepCoverage coverage = sweep_coverage(vertex_neighbours(mesh), deformer.bindings(), deformer.weights());
        if (const std::string problem = describe(coverage, sweep_.measured_radius_scale); !problem.empty())
            summary << "; coverage: " << problem;
        return summary.str();
    }

private:
    MultiResolutionSweep initial(const TriangleMeshData& mesh) const {
        return at_node(sweep_.node, [&] { return MultiResolutionSweep(sweep_.key_sections(&mesh), levels_, sweep_.spline); });
    }
    void edit(MultiResolutionSweep& sweep) const {
        for (const EditSpec& e : edits_) at_node(e.node, [&] { sweep.edit(e.level, e.key, e.edit); });
    }

    SweepSpec sweep_;
    bool local_;
    int levels_;
    bool weights_as_uv_;
    WeightCurve weight_;
    std::vector<EditSpec> edits_;
};

class HierarchyDeformer final : public SweepFamilyDeformer {
public:
    explicit HierarchyDeformer(const SceneNode& node)
        : preserve_volume_(node.boolean_or("preserve_volume", false)),
          max_iterations_(node.integer_or("max_iterations", 50, NumberRange::between(1, 10000))),
          blend_(node.number_or("blend", 0.5, NumberRange::between(0, 10))) {
        for (const SceneNode& s : node.object_array("sweeps")) {
            Member m{parse_sweep_spec(s), s.string_or("parent", ""), Attachment::root, parse_vertex_group(s)};
            if (m.sweep.name.empty()) s.fail("every sweep of a hierarchy needs a \"name\"");
            if (!m.parent.empty()) {
                if (index_of(m.parent) < 0) s.fail_at("parent", "no earlier sweep is called \"" + m.parent + "\"");
                m.attachment = s.choice_or("attachment", "branch", {"branch", "loop"}) == "loop" ? Attachment::loop : Attachment::branch;
            }
            if (index_of(m.sweep.name) >= 0) s.fail_at("name", "two sweeps are called \"" + m.sweep.name + "\"");
            s.finish();
            members_.push_back(std::move(m));
        }
        if (members_.empty() || !members_[0].parent.empty()) node.fail("the first of \"sweeps\" must be the root (no parent)");
        for (const SceneNode& edit : node.object_array("edits")) {
            EditSpec e = parse_edit_spec(edit, true);
            if (index_of(e.sweep) < 0) edit.fail_at("sweep", "no sweep is called \"" + e.sweep + "\"");
            edits_.push_back(std::move(e));
        }
    }

    Cost cost(const TriangleMeshData& mesh) const override {
        const std::uint64_t vertices = mesh.positions.size();
        std::uint64_t samples = 0, rebuild = 0, probe = 0;
        for (const Member& m : members_) {
            const std::uint64_t keys = capped(m.sweep.keys.size());
            samples = saturating_sum({samples, SweepBinder::sample_count(keys)});
            const std::uint64_t rebuilds = preserve_volume_ ? kVolumeRebuilds : 1;
            rebuild = saturating_sum({rebuild, construction_steps(m.sweep, keys) * rebuilds});
            probe = std::max(probe, probe_bytes(m.sweep, mesh));
        }
        // Every vertex is bound to every sweep; the tree is built, and after each edit every sweep may be rebuilt.
        Cost cost{saturating_sum({saturating_product({vertices, samples + kBindingStepsPerVertex * members_.size()}),
                                  saturating_product({rebuild, edits_.size() + 1})}),
                  saturating_sum({saturating_product({vertices, kHierarchyBytesPerVertex}),
                                  saturating_product({vertices, members_.size(), kHierarchyBytesPerBinding}),
                                  samples * kBinderBytesPerSample, probe})};
        std::uint64_t solver_bytes = 0;
        for (const EditSpec& e : edits_) {
            const int pulled = index_of(e.sweep);
            if (!e.pull || pulled < 0 || index_of(members_[std::size_t(pulled)].parent) < 0) continue;
            // A pull's iteration: a finite difference per unknown (4 per key section of the parent, each a rebuilt
            // parent), then up to 8 damped normal equations built and solved.
            const SweepSpec& parent = members_[std::size_t(index_of(members_[std::size_t(pulled)].parent))].sweep;
            const std::uint64_t keys = capped(parent.keys.size()), unknowns = 4 * keys;
            const std::uint64_t solve = unknowns * unknowns * unknowns / 3 + 3 * unknowns * unknowns;
            const std::uint64_t iteration = saturating_sum({unknowns * construction_steps(parent, keys), 8 * solve});
            cost.steps = saturating_sum({cost.steps, saturating_product({std::uint64_t(max_iterations_), iteration})});
            solver_bytes = std::max(solver_bytes, 2 * unknowns * unknowns * sizeof(double));  // normal matrix, its copy
        }
        cost.peak_bytes = saturating_sum({cost.peak_bytes, solver_bytes});
        return cost;
    }

    std::vector<SweepSurface> sweeps(const TriangleMeshData& mesh, bool edited) const override {
        SweepHierarchy tree = build(mesh);
        if (edited) edit(tree);
        std::vector<SweepSurface> surfaces;
        for (std::size_t n = 0; n < tree.size(); ++n) surfaces.push_back(tree.surface(int(n)));
        return surfaces;
    }

    std::string apply(TriangleMeshData& mesh) const override {
        SweepHierarchy tree = build(mesh);
        const auto binding_start = std::chrono::steady_clock::now();
        const std::vector<Vec3d> points = positions_of(mesh);
        std::vector<std::vector<std::optional<VertexBinding>>> bindings(tree.size());
        for (std::size_t n = 0; n < tree.size(); ++n) {
            const SweepBinder binder(tree.surface(int(n)));
            bindings[n].resize(points.size());
            parallel_for(std::size_t(0), points.size(), [&](std::size_t i) { bindings[n][i] = binder.bind(points[i]); });
        }
        const VertexNeighbours next = vertex_neighbours(mesh);
        const std::vector<int> owner = assign_sweeps(mesh, next, bindings, grouped(mesh));
        std::vector<double> widths;
        for (std::size_t n = 0; n < tree.size(); ++n) widths.push_back(blend_ * mean_radius(tree.surface(int(n))));
        const std::vector<std::vector<SweepShare>> shares = blend_sweeps(mesh, next, bindings, owner, widths);
        const double binding_seconds = seconds_since(binding_start);
        const auto deformation_start = std::chrono::steady_clock::now();
        const std::string pulls = edit(tree);
        std::vector<std::size_t> counts(tree.size(), 0);
        std::size_t unbound = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (owner[i] < 0 || !bindings[std::size_t(owner[i])][i]) {
                ++unbound;
                continue;
            }
            ++counts[std::size_t(owner[i])];
            Vec3d moved;
            for (const SweepShare& s : shares[i])
                moved += s.weight * bound_position(tree.surface(s.sweep), *bindings[std::size_t(s.sweep)][i]);
            mesh.positions[i] = Vec3f(moved);
        }
        std::ostringstream head;
        head << "sweep hierarchy: " << points.size() << " vertices";
        for (std::size_t n = 0; n < tree.size(); ++n) head << ", " << counts[n] << " on " << tree.name(int(n));
        head << ", " << unbound << " unbound; binding " << binding_seconds << " s, deformation "
             << seconds_since(deformation_start) << " s";
        if (tree.preserves_volume()) {
            head << "; volume ratios to the parent, now over before:";
            for (std::size_t n = 1; n < tree.size(); ++n) head << " " << tree.name(int(n)) << " " << tree.volume_ratio_drift(int(n));
        }
        return head.str() + pulls;
    }

private:
    // The sweep each vertex's explicit group puts it in (−1: none); empty when no sweep has a group.
    std::vector<int> grouped(const TriangleMeshData& mesh) const {
        std::vector<std::string> names;
        for (const Member& m : members_) names.push_back(m.sweep.name);
        std::vector<int> groups;
        for (std::size_t n = 0; n < members_.size(); ++n) {
            if (!members_[n].group) continue;
            groups.resize(mesh.positions.size(), -1);
            mark_vertex_group(*members_[n].group, mesh, int(n), names, groups);
        }
        return groups;
    }

    SweepHierarchy build(const TriangleMeshData& mesh) const {
        SweepHierarchy tree(preserve_volume_);
        for (const Member& m : members_)
            at_node(m.sweep.node, [&] {
                std::vector<KeySection> keys = m.sweep.key_sections(&mesh);
                return m.parent.empty() ? tree.add_root(m.sweep.name, std::move(keys), m.sweep.spline)
                                        : tree.add_child(m.sweep.name, std::move(keys), index_of(m.parent), m.attachment,
                                                         m.sweep.spline);
            });
        return tree;
    }

    // Applies the edits in order; returns the pulls' residuals for the summary.
    std::string edit(SweepHierarchy& tree) const {
        std::ostringstream summary;
        for (const EditSpec& e : edits_) {
            const int node = index_of(e.sweep);
            at_node(e.node, [&] {
                if (e.key >= int(tree.surface(node).keys().size()))
                    throw std::invalid_argument("key: " + e.sweep + " has key sections 0 to " +
                                                std::to_string(tree.surface(node).keys().size() - 1));
                if (e.pull) {
                    const BackwardResult result =
                        tree.pull(node, {{e.key, tree.surface(node).keys()[std::size_t(e.key)].centre + *e.pull}}, max_iterations_);
                    if (!result.converged) {
                        std::ostringstream problem;
                        if (result.iterations < max_iterations_ && !result.limit.empty()) {  // stalled at a limit
                            problem << "pull: the target is out of reach: residual " << result.residual << " after "
                                    << result.iterations << " iterations; going further, " << result.limit;
                        } else {
                            problem << "pull: backward deformation did not converge: residual " << result.residual << " after "
                                    << result.iterations << " iterations (max_iterations " << max_iterations_ << ")";
                            if (!result.limit.empty()) problem << "; steps were held back: " << result.limit;
                        }
                        throw std::invalid_argument(problem.str());
                    }
                    summary << "; pull of " << e.sweep << "[" << e.key << "]: residual " << result.residual << " after "
                            << result.iterations << " iterations";
                    return;
                }
                std::vector<RelativeKeySection> chain = to_relative(tree.surface(node).keys());
                edit_key_section(chain, std::size_t(e.key), e.edit);
                tree.set_keys(node, to_absolute(chain));
            });
        }
        return summary.str();
    }

    struct Member {
        SweepSpec sweep;
        std::string parent;
        Attachment attachment;
        std::optional<VertexGroupSpec> group;
    };
    int index_of(const std::string& name) const {
        for (std::size_t i = 0; i < members_.size(); ++i)
            if (members_[i].sweep.name == name) return int(i);
        return -1;
    }

    bool preserve_volume_;
    int max_iterations_;
    double blend_;
    std::vector<Member> members_;
    std::vector<EditSpec> edits_;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(mesh_deformer_registry, "sweep",
                         "sweep-based free-form deformation: key_sections, name, mode (local/global), weight_curve, levels, "
                         "edits, radius_samples, relative, measure, measured_radius_scale, spline, weights_as_uv",
                         [](const SceneNode& node) -> std::unique_ptr<MeshDeformer> { return std::make_unique<SingleSweepDeformer>(node); })
ISOTRACE_REGISTER_PLUGIN(mesh_deformer_registry, "sweep_hierarchy",
                         "tree of sweeps (branch/loop children): sweeps, edits (incl. pull), preserve_volume, max_iterations, blend",
                         [](const SceneNode& node) -> std::unique_ptr<MeshDeformer> { return std::make_unique<HierarchyDeformer>(node); })

}  // namespace isotrace
