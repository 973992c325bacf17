#include "geometry/superquadric/deformation_chain.h"

#include <limits>
#include <stdexcept>

namespace isotrace {
namespace {

// Widens every side by a small fraction of the box's size, so that the surface lies strictly inside the box
// (a superellipsoid touches its box at the axis ends) and rounding in the bounds cannot cut it.
IntervalBox widened(IntervalBox box) {
    double size = 0;
    for (int k = 0; k < 3; ++k) size = std::max({size, std::abs(box[k].lo), std::abs(box[k].hi)});
    const double margin = 1e-9 * size;
    for (int k = 0; k < 3; ++k) box[k] = {box[k].lo - margin, box[k].hi + margin};
    return box;
}

}  // namespace

DeformationChain::DeformationChain(const Superellipsoid& shape)
    : shape_(shape),
      boxes_{widened(shape.bounding_box())},
      heights_{-shape.radii().z, shape.radii().z},
      cone_(shape.enclosing_cylinder()),
      convex_levels_(shape.is_convex() ? std::numeric_limits<double>::infinity() : 0) {}

void DeformationChain::append(const Deformation& stage) {
    if (stages_.size() >= std::size_t(kMaxStages))
        throw std::invalid_argument("at most " + std::to_string(kMaxStages) + " deformations are supported");
    const std::string problem = std::visit([&](const auto& s) { return s.problem(boxes_.back()); }, stage);
    if (!problem.empty()) throw std::invalid_argument(problem);
    stages_.push_back(stage);
    // The levels known convex: a twist turns a solid of revolution about z onto itself, level sets and all, and so
    // keeps what was known; a taper of the shape's own level sets (those of a convex shape, undeformed or only
    // turned) keeps Taper::convex_levels; nothing else is known.
    const Taper* taper = std::get_if<Taper>(&stage);
    if (std::holds_alternative<Twist>(stage)) {
        if (!shape_.is_round_about_z()) convex_levels_ = 0;
    } else if (taper && convex_levels_ == std::numeric_limits<double>::infinity()) {
        convex_levels_ = taper->convex_levels(2 / shape_.north_south());
    } else {
        convex_levels_ = 0;
    }
    keeps_solids_of_revolution_ =
        keeps_solids_of_revolution_ && std::visit([](const auto& s) { return s.keeps_solids_of_revolution(); }, stage);
    sector_ = std::visit([&](const auto& s) { return s.sector(boxes_.back(), heights_, cone_); }, stage);
    if (cone_) cone_ = std::visit([&](const auto& s) { return s.carry(*cone_); }, stage);
    compute_stage_boxes();
    if (!std::visit([](const auto& s) { return s.keeps_heights(); }, stage)) heights_ = boxes_.back().z;
    // The cone's radius must stay positive over the box, where rays are asked.
    const Interval z = boxes_.back().z;
    if (cone_ && !(cone_->radius_scale(z.lo) > 0 && cone_->radius_scale(z.hi) > 0)) cone_.reset();
}

void DeformationChain::compute_stage_boxes() {
    constexpr int kCellsPerAxis = 8;
    std::vector<IntervalBox> cells = shape_.surface_cells(kCellsPerAxis);
    boxes_.resize(1);
    for (const Deformation& stage : stages_) {
        IntervalBox box = std::visit([&](const auto& s) { return s.forward_box(cells[0]); }, stage);
        for (IntervalBox& cell : cells) {
            cell = std::visit([&](const auto& s) { return s.forward_box(cell); }, stage);
            box.extend(cell.lower());
            box.extend(cell.upper());
        }
        boxes_.push_back(widened(box));
    }
}

Vec3d DeformationChain::forward(const Vec3d& p) const {
    Vec3d q = p;
    for (const Deformation& stage : stages_) q = std::visit([&](const auto& s) { return s.forward(q); }, stage);
    return q;
}

template <class Invert>
std::optional<Vec3d> DeformationChain::walk_inverse(const Vec3d& q, bool check_boxes, BeyondUndeformedBox beyond,
                                                    Invert&& invert) const {
    Vec3d point = q;
    for (std::size_t k = stages_.size(); k > 0; --k) {
        if (check_boxes && !boxes_[k].contains(point)) return std::nullopt;
        point = std::visit([&](const auto& s) { return invert(k - 1, s, point); }, stages_[k - 1]);
    }
    // Undeformed, no box is needed: the gauge exceeds 1 everywhere outside the superellipsoid's box, and a box
    // check would only turn the value at a ray's rounded entry point into the constant 1 (no slope for Newton). A
    // deformed object's undeformed box counts as a stage box unless the walk goes on beyond it.
    if (check_boxes && beyond == BeyondUndeformedBox::Outside && !stages_.empty() && !boxes_[0].contains(point))
        return std::nullopt;
    return point;
}

std::optional<Vec3d> DeformationChain::inverse(const Vec3d& q, BeyondUndeformedBox beyond) const {
    return walk_inverse(q, true, beyond, [](std::size_t, const auto& stage, const Vec3d& image) { return stage.inverse(image); });
}

std::optional<Vec3d> DeformationChain::inverse_along(const Vec3d& q, Vec3d& velocity) const {
    Vec3d along = velocity;
    // A stage that takes its inverse and Jacobian together shares their work (a twist's sine and cosine).
    const auto carry_back = [&](std::size_t, const auto& stage, const Vec3d& image) {
        if constexpr (requires { stage.inverse_and_jacobian(image); }) {
            const auto [preimage, jacobian] = stage.inverse_and_jacobian(image);
            along = jacobian.solve(along);
            return preimage;
        } else {
            const Vec3d preimage = stage.inverse(image);
            along = stage.jacobian(preimage).solve(along);
            return preimage;
        }
    };
    const std::optional<Vec3d> point = walk_inverse(q, true, BeyondUndeformedBox::Gauge, carry_back);
    if (point) velocity = along;
    return point;
}

DeformationChain::Path DeformationChain::inverse_path(const Vec3d& q) const {
    Path path;
    path[stages_.size()] = q;
    walk_inverse(q, false, BeyondUndeformedBox::Outside, [&](std::size_t stage, const auto& s, const Vec3d& image) {
        return path[stage] = s.inverse(image);
    });
    return path;
}

bool DeformationChain::inverse_boxes(IntervalBox box, InverseBoxes& boxes, BeyondUndeformedBox beyond) const {
    boxes.clipped = false;
    const auto clip_to_stage = [&](IntervalBox& b, std::size_t stage) {
        const IntervalBox before = b;
        if (!clip_box(b, boxes_[stage])) return false;
        boxes.clipped = boxes.clipped || before.lower() != b.lower() || before.upper() != b.upper();
        return true;
    };
    if (!clip_to_stage(box, stages_.size())) return false;
    boxes.stage[stages_.size()] = box;
    for (std::size_t k = stages_.size(); k > 0; --k) {
        IntervalBox preimage = std::visit([&](const auto& s) { return s.inverse_box(boxes.stage[k]); }, stages_[k - 1]);
        if ((k > 1 || beyond == BeyondUndeformedBox::Outside) && !clip_to_stage(preimage, k - 1)) return false;
        boxes.stage[k - 1] = preimage;
    }
    return true;
}

Interval DeformationChain::gauge_slope(const InverseBoxes& boxes, IntervalBox tangent) const {
    return slope_with(boxes, shape_.gradient_range(boxes.stage[0]), tangent);
}

IntervalBox DeformationChain::gauge_gradient(const InverseBoxes& boxes) const {
    const IntervalBox gradient = shape_.gradient_range(boxes.stage[0]);
    IntervalBox along_axes;
    for (int k = 0; k < 3; ++k) along_axes[k] = slope_with(boxes, gradient, IntervalBox::point(Vec3d(k == 0, k == 1, k == 2)));
    return along_axes;
}

Interval DeformationChain::slope_with(const InverseBoxes& boxes, const IntervalBox& gradient, IntervalBox tangent) const {
    if (!gradient.is_finite()) return Interval::unbounded();
    for (std::size_t k = stages_.size(); k > 0; --k)
        tangent = std::visit([&](const auto& s) { return s.inverse_tangent(boxes.stage[k - 1], tangent); }, stages_[k - 1]);
    return gradient.x * tangent.x + gradient.y * tangent.y + gradient.z * tangent.z;
}

std::optional<IntervalBox> DeformationChain::inverse_box(const IntervalBox& box, bool& clipped) const {
    InverseBoxes boxes;
    const bool inside = inverse_boxes(box, boxes);
    clipped = boxes.clipped;
    if (!inside) return std::nullopt;
    return boxes.stage[0];
}

Vec3d DeformationChain::deform_normal(const Path& path, const Vec3d& undeformed_normal) const {
    Vec3d n = undeformed_normal;
    for (std::size_t k = 0; k < stages_.size(); ++k) {
        n = normalize(std::visit([&](const auto& s) { return s.jacobian(path[k]); }, stages_[k]).transform_normal(n));
    }
    return n;
}

}  // namespace isotrace
