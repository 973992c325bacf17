#include "geometry/sweep/sweep_deformer.h"

#include <stdexcept>

#include "geometry/sweep/sweep_surface.h"
#include "renderer/core/parallel_for.h"

namespace isotrace {

SweepDeformer::SweepDeformer(const SweepSurface& sweep, const std::vector<Vec3d>& points, Mode mode,
                             const WeightCurve& weight, const std::vector<bool>* selected)
    : points_(points), bindings_(points.size()), weights_(points.size(), 0.0) {
    if (selected && selected->size() != points.size())
        throw std::invalid_argument("selection: one flag per point needed");
    const SweepBinder binder(sweep);
    parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
        if (selected && !(*selected)[i]) return;
        bindings_[i] = binder.bind(points[i]);
        if (!bindings_[i]) return;
        const VertexBinding& b = *bindings_[i];
        if (mode == Mode::global) {
            weights_[i] = 1;
        } else if (b.d <= 0) {
            const double r = sweep.radius(b.theta, b.t);
            weights_[i] = weight((r + b.d) / r);
        }
    });
    statistics_.points = points.size();
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!bindings_[i]) continue;
        ++statistics_.bound;
        if (bindings_[i]->d <= 0) ++statistics_.inside;
        if (weights_[i] > 0) ++statistics_.weighted;
    }
}

std::vector<Vec3d> SweepDeformer::deform(const SweepSurface& edited) const {
    std::vector<Vec3d> moved(points_);
    parallel_for(std::size_t(0), points_.size(), [&](std::size_t i) {
        if (weights_[i] == 0) return;
        moved[i] = points_[i] + weights_[i] * (bound_position(edited, *bindings_[i]) - points_[i]);
    });
    return moved;
}

}  // namespace isotrace
