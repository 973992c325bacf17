#include "renderer/plugin/solid.h"

namespace isotrace {

std::optional<BoundaryPoint> first_surface_crossing(std::span<const InsideSpan> spans, double t_near, double t_far) {
    for (const InsideSpan& span : spans)
        for (const BoundaryPoint* end : {&span.enter, &span.exit}) {
            if (end->t >= t_far) return std::nullopt;
            if (end->on_surface() && end->t > t_near) return *end;
        }
    return std::nullopt;
}

std::optional<BoundaryPoint> Solid::first_surface_point(const Vec3d& origin, const Vec3d& direction, double t_near,
                                                        double t_far, QueryScratch& scratch) const {
    if (!(t_near < t_far)) return std::nullopt;
    const QueryScratch::Level level(scratch);
    auto& spans = level.get<std::vector<InsideSpan>>();
    spans.clear();
    inside_spans(origin, direction, t_near, t_far, spans, scratch);
    return first_surface_crossing(spans, t_near, t_far);
}

}  // namespace isotrace
