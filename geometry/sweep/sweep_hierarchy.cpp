#include "geometry/sweep/sweep_hierarchy.h"

#include <cmath>
#include <stdexcept>

#include "geometry/curves/dense_solve.h"
#include "geometry/sweep/sweep_fold.h"
#include "geometry/sweep/sweep_volume.h"

namespace isotrace {
namespace {

BoundKeySection bind_key(const SweepSurface& parent, const KeySection& key, const std::string& field) {
    const std::optional<VertexBinding> binding = SweepBinder(parent).bind(key.centre);
    if (!binding) throw std::invalid_argument(field + ": its centre lies on no cross-section plane of the parent sweep");
    return {*binding, parent.orientation(binding->t).conjugate() * key.orientation};
}

KeySection placed(const SweepSurface& parent, const BoundKeySection& bound, std::vector<double> radii) {
    return {bound_position(parent, bound.position), normalize(parent.orientation(bound.position.t) * bound.orientation),
            std::move(radii)};
}

std::vector<KeySection> with_radius_scale(std::vector<KeySection> keys, double scale) {
    for (KeySection& key : keys)
        for (double& r : key.radii) r *= scale;
    return keys;
}

}  // namespace

int SweepHierarchy::add_root(std::string name, std::vector<KeySection> keys, SweepSpline spline) {
    SweepSurface surface(keys, {}, spline);
    std::vector<double> parameters = surface.key_parameters();
    nodes_.push_back({std::move(name), -1, Attachment::root, std::move(surface), std::move(parameters), to_relative(keys), {}, 1});
    return int(nodes_.size()) - 1;
}

int SweepHierarchy::add_child(std::string name, std::vector<KeySection> keys, int parent, Attachment attachment,
                              SweepSpline spline) {
    if (parent < 0 || parent >= int(nodes_.size())) throw std::invalid_argument(name + ".parent: no such sweep");
    if (attachment == Attachment::root) throw std::invalid_argument(name + ".attachment: a child is a branch or a loop");
    SweepSurface surface(keys, {}, spline);
    std::vector<double> parameters = surface.key_parameters();
    Node node{name, parent, attachment, std::move(surface), std::move(parameters), to_relative(keys), {}, 1};
    const SweepSurface& parent_surface = nodes_[std::size_t(parent)].surface;
    const std::size_t bound_count = attachment == Attachment::loop ? keys.size() : 1;
    for (std::size_t k = 0; k < bound_count; ++k)
        node.bound.push_back(bind_key(parent_surface, keys[k], name + ".key_sections[" + std::to_string(k) + "]"));
    if (preserve_volume_) node.volume_ratio = sweep_volume(node.surface) / sweep_volume(parent_surface);
    nodes_.push_back(std::move(node));
    return int(nodes_.size()) - 1;
}

std::vector<KeySection> SweepHierarchy::placed_keys(const Node& child, const SweepSurface& parent) const {
    if (child.attachment == Attachment::loop) {
        std::vector<KeySection> keys;
        for (std::size_t k = 0; k < child.bound.size(); ++k) keys.push_back(placed(parent, child.bound[k], child.shape[k].radii));
        return keys;
    }
    // Branch: the first key where the parent puts it, the others relative to it as before.
    const KeySection first = placed(parent, child.bound[0], child.shape[0].radii);
    std::vector<RelativeKeySection> relative = child.shape;
    relative[0] = {first.centre, first.orientation, first.radii};
    return to_absolute(relative);
}

void SweepHierarchy::scale_to_volume(int index, double target) {
    Node& node = nodes_[std::size_t(index)];
    const std::vector<KeySection> keys = node.surface.keys();
    auto volume_at = [&](double scale) {
        return sweep_volume(SweepSurface(with_radius_scale(keys, scale), node.parameters, node.surface.spline()));
    };
    // Secant on the radius scale, starting from the area law V ∝ s².
    double s0 = 1, v0 = volume_at(1);
    double s1 = std::sqrt(std::max(target / v0, 1e-6)), v1 = volume_at(s1);
    for (int iteration = 0; iteration < 40 && std::abs(v1 - target) > 1e-9 * std::abs(target) && v1 != v0; ++iteration) {
        const double s2 = std::max(s1 - (v1 - target) * (s1 - s0) / (v1 - v0), 1e-3);
        s0 = s1;
        v0 = v1;
        s1 = s2;
        v1 = volume_at(s1);
    }
    for (RelativeKeySection& key : node.shape)
        for (double& r : key.radii) r *= s1;
    node.surface = SweepSurface(with_radius_scale(keys, s1), node.parameters, node.surface.spline());
}

double SweepHierarchy::volume_ratio_drift(int child) const {
    const Node& node = nodes_[std::size_t(child)];
    const double ratio = sweep_volume(node.surface) / sweep_volume(nodes_[std::size_t(node.parent)].surface);
    return preserve_volume_ ? ratio / node.volume_ratio : 1;
}

void SweepHierarchy::place_children(int node) {
    for (std::size_t c = 0; c < nodes_.size(); ++c) {
        if (nodes_[c].parent != node) continue;
        nodes_[c].surface = SweepSurface(placed_keys(nodes_[c], nodes_[std::size_t(node)].surface), nodes_[c].parameters,
                                         nodes_[c].surface.spline());
        if (preserve_volume_) scale_to_volume(int(c), nodes_[c].volume_ratio * sweep_volume(nodes_[std::size_t(node)].surface));
        place_children(int(c));
    }
}

void SweepHierarchy::set_keys(int node, std::vector<KeySection> keys) {
    Node& n = nodes_[std::size_t(node)];
    if (n.attachment == Attachment::loop)
        throw std::invalid_argument(n.name + ": a loop-bound sweep is edited through its parent (backward deformation)");
    if (keys.size() != n.parameters.size())
        throw std::invalid_argument(n.name + ".key_sections: the sweep has " + std::to_string(n.parameters.size()) +
                                    " key sections, got " + std::to_string(keys.size()));
    SweepSurface surface(keys, n.parameters, n.surface.spline());
    if (n.attachment == Attachment::branch)
        n.bound[0] = bind_key(nodes_[std::size_t(n.parent)].surface, keys[0], n.name + ".key_sections[0]");
    n.shape = to_relative(keys);
    n.surface = std::move(surface);
    // Rule 3 upwards: an edited child changes its ancestors' volumes by the same factor, so that every ratio
    // stays; re-placing from the highest of them then carries the edited child and its siblings along.
    int top = node;
    for (int child = node; preserve_volume_ && nodes_[std::size_t(child)].parent >= 0; child = top) {
        const Node& c = nodes_[std::size_t(child)];
        top = c.parent;
        scale_to_volume(top, sweep_volume(c.surface) / c.volume_ratio);
    }
    place_children(top);
}

BackwardResult SweepHierarchy::pull(int loop_child, const std::vector<std::pair<int, Vec3d>>& targets, int max_iterations) {
    const Node& child = nodes_[std::size_t(loop_child)];
    if (child.attachment != Attachment::loop) throw std::invalid_argument(child.name + ": only loop-bound sweeps are pulled");
    if (max_iterations < 1) throw std::invalid_argument("max_iterations: must be ≥ 1");
    for (const auto& [key, target] : targets)
        if (key < 0 || key >= int(child.bound.size()) || !is_finite(target))
            throw std::invalid_argument(child.name + ".targets: key " + std::to_string(key) + " is not a key section or its target is not finite");
    const int parent = child.parent;
    if (nodes_[std::size_t(parent)].attachment == Attachment::loop)
        throw std::invalid_argument(child.name + ": its parent is itself loop-bound (not supported)");
    const std::vector<KeySection> start = nodes_[std::size_t(parent)].surface.keys();
    const double size = nodes_[std::size_t(parent)].surface.size();
    const std::size_t unknowns = 4 * start.size(), equations = 3 * targets.size();

    // x: per parent key a centre offset (3) and a radius log-scale in units of the parent's size (1).
    auto parent_keys = [&](const std::vector<double>& x) {
        std::vector<KeySection> keys = start;
        for (std::size_t k = 0; k < keys.size(); ++k) {
            keys[k].centre = keys[k].centre + Vec3d(x[4 * k], x[4 * k + 1], x[4 * k + 2]);
            for (double& r : keys[k].radii) r *= std::exp(x[4 * k + 3] / size);
        }
        return keys;
    };
    const SweepSurface& start_surface = nodes_[std::size_t(parent)].surface;
    const std::string& parent_name = nodes_[std::size_t(parent)].name;
    auto residual = [&](const SweepSurface& p) {
        std::vector<double> e;
        for (const auto& [key, target] : targets) {
            const Vec3d at = bound_position(p, child.bound[std::size_t(key)].position);
            for (int a = 0; a < 3; ++a) e.push_back(target[a] - at[a]);
        }
        return e;
    };
    auto rms = [&](const std::vector<double>& e) {
        double sum = 0;
        for (double v : e) sum += v * v;
        return std::sqrt(sum / double(targets.size()));
    };

    auto surface_of = [&](const std::vector<double>& x) {
        return SweepSurface(parent_keys(x), nodes_[std::size_t(parent)].parameters, start_surface.spline());
    };
    // Why the parent `p` may not be used ("" when it may).
    auto refusal = [&](const SweepSurface& p) -> std::string {
        if (std::string fold = sweep_fold(p); !fold.empty()) return "the " + parent_name + " sweep's " + fold;
        if (sweep_stretch(start_surface, p) > kMaxPullStretch)
            return "the " + parent_name + " sweep would stretch or shrink more than " + std::to_string(int(kMaxPullStretch)) + "×";
        return {};
    };
    // The step metric: identity plus kPullSmoothness × the squared differences of neighbouring keys' unknowns.
    std::vector<double> metric(unknowns * unknowns, 0.0);
    for (std::size_t a = 0; a < unknowns; ++a) metric[a * unknowns + a] = 1;
    for (std::size_t k = 0; k + 1 < start.size(); ++k)
        for (std::size_t c = 0; c < 4; ++c) {
            const std::size_t a = 4 * k + c, b = 4 * (k + 1) + c;
            metric[a * unknowns + a] += kPullSmoothness;
            metric[b * unknowns + b] += kPullSmoothness;
            metric[a * unknowns + b] -= kPullSmoothness;
            metric[b * unknowns + a] -= kPullSmoothness;
        }
    std::vector<double> x(unknowns, 0.0), e = residual(start_surface);
    BackwardResult result;
    result.residual = rms(e);
    std::string refused;  // why the last refused step was refused
    double damping = 0.1 * size;
    const double h = 1e-7 * size;
    while (result.iterations < max_iterations && result.residual > kBackwardTolerance * size) {
        ++result.iterations;
        std::vector<double> jacobian(equations * unknowns);  // d(position)/dx = −d(e)/dx
        for (std::size_t j = 0; j < unknowns; ++j) {
            std::vector<double> shifted = x;
            shifted[j] += h;
            const std::vector<double> e2 = residual(surface_of(shifted));
            for (std::size_t i = 0; i < equations; ++i) jacobian[i * unknowns + j] = (e[i] - e2[i]) / h;
        }
        // (JᵀJ + λ²I)·Δx = Jᵀe; a step that does not reduce the residual raises λ, a good one lowers it.
        bool improved = false;
        for (int attempt = 0; attempt < 8 && !improved; ++attempt) {
            std::vector<double> normal(unknowns * unknowns, 0.0), rhs(unknowns, 0.0);
            for (std::size_t a = 0; a < unknowns; ++a) {
                for (std::size_t i = 0; i < equations; ++i) rhs[a] += jacobian[i * unknowns + a] * e[i];
                for (std::size_t b = 0; b < unknowns; ++b) {
                    double sum = damping * damping * metric[a * unknowns + b];
                    for (std::size_t i = 0; i < equations; ++i) sum += jacobian[i * unknowns + a] * jacobian[i * unknowns + b];
                    normal[a * unknowns + b] = sum;
                }
            }
            const std::vector<double> step = solve_dense(std::move(normal), std::move(rhs));
            std::vector<double> trial = x;
            for (std::size_t a = 0; a < unknowns; ++a) trial[a] += step[a];
            std::vector<double> trial_e;
            try {
                const SweepSurface p = surface_of(trial);
                if (std::string why = refusal(p); !why.empty()) {  // a valid parent only: damp more
                    refused = std::move(why);
                    damping *= 4;
                    continue;
                }
                trial_e = residual(p);
            } catch (const std::invalid_argument& broken) {  // coinciding keys: damp more
                refused = "the " + parent_name + " sweep would break (" + broken.what() + ")";
                damping *= 4;
                continue;
            }
            if (rms(trial_e) < result.residual) {
                x = std::move(trial);
                e = std::move(trial_e);
                result.residual = rms(e);
                damping = std::max(damping / 3, 1e-6 * size);
                improved = true;
            } else {
                damping *= 4;
            }
        }
        if (!improved) break;  // stalled: the targets are out of reach
    }
    result.converged = result.residual <= kBackwardTolerance * size;
    if (!result.converged) result.limit = refused;
    set_keys(parent, parent_keys(x));
    return result;
}

}  // namespace isotrace
