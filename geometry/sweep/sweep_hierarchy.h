#pragma once
// A tree of sweeps (the paper's §5, Fig. 7): each child's key sections are bound to its parent's sweep as
// K = (θ, t, d, q̂ = q(t)⁻¹·q) (eq. 10) and placed back by eq. (11) after the parent changes.
//   branch child (the teapot's spout): only its first key section is bound; the others follow it as relative key
//     sections, so the branch keeps its own shape.
//   loop child (the handle): every key section is bound, so both ends stay attached to the parent.
// Rules: (1) forward deformation — editing a node re-places all its descendants; (2) backward deformation — a
// loop child cannot be edited directly (it would tear away from the parent): moving its key sections towards
// targets is achieved by editing the parent instead, by damped least squares on the parent's key centres and
// radius scales (target tracking), with a convergence test, an iteration cap and the residual reported. The
// damping measures a step with a smoothness metric (neighbouring keys' changes differing cost more), so the
// parent bends as a whole rather than kinking at one key, and a step that would leave the parent invalid — its
// sections crossing (sweep_fold.h) or any of its lengths stretched or shrunk beyond kMaxPullStretch — is
// refused like one that does not help: a target that needs such a parent is out of reach and reported so;
// (3) optional volume-ratio preservation, both ways as the paper has it — after an edit each descendant's radii are
// scaled (solved numerically) so that its volume keeps its ratio to its parent's volume (general volume formula),
// and an edited child's ancestors are scaled first so that their ratios to it are kept too.
#include <optional>
#include <string>
#include <vector>

#include "geometry/sweep/key_section.h"
#include "geometry/sweep/sweep_surface.h"
#include "geometry/sweep/vertex_binding.h"

namespace isotrace {

enum class Attachment { root, branch, loop };

struct BoundKeySection {
    VertexBinding position;    // the key centre, bound to the parent sweep
    Quaternion orientation;    // q̂ = q(t)⁻¹·q, relative to the parent's section frame at t
};

struct BackwardResult {
    int iterations = 0;
    double residual = 0;  // RMS distance of the targeted keys from their targets after the last iteration
    bool converged = false;
    std::string limit;    // when not converged: why its last refused step was refused ("the body sweep's sections ... cross")
};

class SweepHierarchy {
public:
    // Tolerance of the backward deformation's convergence test, relative to the parent sweep's size.
    static constexpr double kBackwardTolerance = 1e-6;
    // How far a pull may stretch (or shrink) the parent's axis and radii: its reach.
    static constexpr double kMaxPullStretch = 2;
    // Weight of the differences of neighbouring keys' changes in the step metric, against the changes themselves.
    static constexpr double kPullSmoothness = 10;

    // `preserve_volume`: rule 3 (each child's volume ratio to its parent, measured when it is added, is kept).
    explicit SweepHierarchy(bool preserve_volume = false) : preserve_volume_(preserve_volume) {}

    int add_root(std::string name, std::vector<KeySection> keys, SweepSpline spline = SweepSpline::cubic);
    // Binds the child's key sections (the first or all) to the parent's current sweep. Throws
    // std::invalid_argument "<name>.key_sections[k]: ..." when a key section to be bound has no binding.
    int add_child(std::string name, std::vector<KeySection> keys, int parent, Attachment attachment,
                  SweepSpline spline = SweepSpline::cubic);

    std::size_t size() const { return nodes_.size(); }
    const std::string& name(int node) const { return nodes_[std::size_t(node)].name; }
    int parent(int node) const { return nodes_[std::size_t(node)].parent; }
    Attachment attachment(int node) const { return nodes_[std::size_t(node)].attachment; }
    const SweepSurface& surface(int node) const { return nodes_[std::size_t(node)].surface; }
    const std::vector<BoundKeySection>& bindings(int node) const { return nodes_[std::size_t(node)].bound; }
    bool preserves_volume() const { return preserve_volume_; }
    // A child's volume ratio to its parent now, over the ratio when it was added (rule 3 keeps it at 1).
    double volume_ratio_drift(int child) const;

    // Rule 1 (and rule 3 when preserve_volume, for the ancestors as well): replaces a root's or branch child's key
    // sections and re-places every descendant. A branch child's first key section is re-bound where it is now. Throws for loop children.
    void set_keys(int node, std::vector<KeySection> keys);
    // Rule 2: moves the loop child's key sections `targets[i].first` towards the points `targets[i].second` by
    // editing its parent (then rule 1 for everything below the parent). `max_iterations` ≥ 1.
    BackwardResult pull(int loop_child, const std::vector<std::pair<int, Vec3d>>& targets, int max_iterations = 50);

private:
    struct Node {
        std::string name;
        int parent = -1;
        Attachment attachment = Attachment::root;
        SweepSurface surface;
        std::vector<double> parameters;          // the keys' t as first placed, kept through edits
        std::vector<RelativeKeySection> shape;  // branch children: the keys after the first, relative
        std::vector<BoundKeySection> bound;
        double volume_ratio = 1;  // volume / parent volume when bound (rule 3 only)
    };
    void place_children(int node);
    std::vector<KeySection> placed_keys(const Node& child, const SweepSurface& parent) const;
    // Scales the node's radii (a secant solve) so that its volume is `target`.
    void scale_to_volume(int node, double target);

    std::vector<Node> nodes_;
    bool preserve_volume_;
};

}  // namespace isotrace
