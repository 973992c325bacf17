// The "sweep" and "sweep_hierarchy" mesh deformers (docs/scene-format.md, "Sweep deformers").

#include <sstream>

#include "geometry/sweep/sweep_deformer.h"
#include "geometry/sweep/sweep_family_deformer.h"
#include "geometry/sweep/sweep_hierarchy.h"
#include "geometry/sweep/sweep_spec.h"
#include "geometry/sweep/sweep_surface.h"
#include "renderer/core/parallel_for.h"

namespace isotrace {
namespace {

// Wall seconds since `start`: the summaries report binding and deformation times (the sweep benchmark).
double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
        return summary.str();
    }

private:
    MultiResolutionSweep initial(const TriangleMeshData& mesh) const {
        return at_node(sweep_.node, [&] { return MultiResolutionSweep(sweep_.key_sections(&mesh), levels_); });
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
          max_iterations_(node.integer_or("max_iterations", 50, NumberRange::between(1, 10000))) {
        for (const SceneNode& s : node.object_array("sweeps")) {
            Member m{parse_sweep_spec(s), s.string_or("parent", ""), Attachment::root};
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

    std::vector<SweepSurface> sweeps(const TriangleMeshData& mesh, bool edited) const override {
        SweepHierarchy tree = build(mesh);
        if (edited) edit(tree);
        std::vector<SweepSurface> surfaces;
        for (std::size_t n = 0; n < tree.size(); ++n) surfaces.push_back(tree.surface(int(n)));
        return surfaces;
    }

    std::string apply(TriangleMeshData& mesh) const override {
        SweepHierarchy tree = build(mesh);
        // Each vertex follows the sweep it lies deepest in: the smallest u = (r + d)/r of its bindings.
        const auto binding_start = std::chrono::steady_clock::now();
        const std::vector<Vec3d> points = positions_of(mesh);
        std::vector<SweepBinder> binders;
        for (std::size_t n = 0; n < tree.size(); ++n) binders.emplace_back(tree.surface(int(n)));
        std::vector<int> owner(points.size(), -1);
        std::vector<VertexBinding> bindings(points.size());
        parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
            double best = INFINITY;
            for (std::size_t n = 0; n < binders.size(); ++n) {
                const auto b = binders[n].bind(points[i]);
                if (!b) continue;
                const double u = 1 + b->d / tree.surface(int(n)).radius(b->theta, b->t);
                if (u < best) {
                    best = u;
                    owner[i] = int(n);
                    bindings[i] = *b;
                }
            }
        });
        const double binding_seconds = seconds_since(binding_start);
        const auto deformation_start = std::chrono::steady_clock::now();
        const std::string pulls = edit(tree);
        std::vector<std::size_t> counts(tree.size(), 0);
        std::size_t unbound = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (owner[i] < 0) {
                ++unbound;
                continue;
            }
            ++counts[std::size_t(owner[i])];
            mesh.positions[i] = Vec3f(bound_position(tree.surface(owner[i]), bindings[i]));
        }
        std::ostringstream head;
        head << "sweep hierarchy: " << points.size() << " vertices";
        for (std::size_t n = 0; n < tree.size(); ++n) head << ", " << counts[n] << " on " << tree.name(int(n));
        head << ", " << unbound << " unbound; binding " << binding_seconds << " s, deformation "
             << seconds_since(deformation_start) << " s";
        return head.str() + pulls;
    }

private:
    SweepHierarchy build(const TriangleMeshData& mesh) const {
        SweepHierarchy tree(preserve_volume_);
        for (const Member& m : members_)
            at_node(m.sweep.node, [&] {
                std::vector<KeySection> keys = m.sweep.key_sections(&mesh);
                return m.parent.empty() ? tree.add_root(m.sweep.name, std::move(keys))
                                        : tree.add_child(m.sweep.name, std::move(keys), index_of(m.parent), m.attachment);
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
                        problem << "pull: backward deformation did not converge: residual " << result.residual << " after "
                                << result.iterations << " iterations (max_iterations " << max_iterations_ << ")";
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
    };
    int index_of(const std::string& name) const {
        for (std::size_t i = 0; i < members_.size(); ++i)
            if (members_[i].sweep.name == name) return int(i);
        return -1;
    }

    bool preserve_volume_;
    int max_iterations_;
    std::vector<Member> members_;
    std::vector<EditSpec> edits_;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(mesh_deformer_registry, "sweep",
                         "sweep-based free-form deformation: key_sections, mode (local/global), weight_curve, levels, edits",
                         [](const SceneNode& node) -> std::unique_ptr<MeshDeformer> { return std::make_unique<SingleSweepDeformer>(node); })
ISOTRACE_REGISTER_PLUGIN(mesh_deformer_registry, "sweep_hierarchy",
                         "tree of sweeps (branch/loop children): sweeps, edits (incl. pull), preserve_volume, max_iterations",
                         [](const SceneNode& node) -> std::unique_ptr<MeshDeformer> { return std::make_unique<HierarchyDeformer>(node); })

}  // namespace isotrace
