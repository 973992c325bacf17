#pragma once
// Sweep-based free-form deformation of a point set (mesh vertices): every point is bound once to the sweep as
// first placed (vertex_binding.h); an edited sweep then moves each bound point by eq. (8), blended by its
// weight. Global mode: weight 1 for every bound point. Local mode (§4.2): inner points (d ≤ 0) get
// w = f((r + d)/r) with r the radius at binding time, outer points 0; v′ = v + w·(v_eq8 − v). Unbound points
// stay where they are and are counted.
#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/sweep/vertex_binding.h"
#include "geometry/sweep/weight_curve.h"

namespace isotrace {

class SweepSurface;

struct BindingStatistics {
    std::size_t points = 0;
    std::size_t bound = 0;
    std::size_t inside = 0;     // bound with d ≤ 0
    std::size_t weighted = 0;   // weight > 0 (all bound points in global mode)
    std::size_t unbound() const { return points - bound; }
};

class SweepDeformer {
public:
    enum class Mode { global, local };

    // Binds `points` (in parallel; deterministic) to `sweep`. Points for which `selected` is false (when given,
    // one flag per point) are neither bound nor moved.
    SweepDeformer(const SweepSurface& sweep, const std::vector<Vec3d>& points, Mode mode,
                  const WeightCurve& weight = {}, const std::vector<bool>* selected = nullptr);

    // The points moved by the edited sweep (same point count and order as at construction).
    std::vector<Vec3d> deform(const SweepSurface& edited) const;

    const BindingStatistics& statistics() const { return statistics_; }
    const std::vector<std::optional<VertexBinding>>& bindings() const { return bindings_; }
    const std::vector<double>& weights() const { return weights_; }  // 0 for unbound points

private:
    std::vector<Vec3d> points_;
    std::vector<std::optional<VertexBinding>> bindings_;
    std::vector<double> weights_;
    BindingStatistics statistics_;
};

}  // namespace isotrace
