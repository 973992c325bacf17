#include "geometry/csg/inside_span_list.h"

namespace isotrace {

void append_clipped_span(InsideSpan span, double t_min, double t_max, std::vector<InsideSpan>& spans) {
    if (span.enter.t < t_min) span.enter = {t_min, span.enter.normal, BoundaryPoint::kCut, span.enter.part};
    if (span.exit.t > t_max) span.exit = {t_max, span.exit.normal, BoundaryPoint::kCut, span.exit.part};
    if (span.enter.t < span.exit.t) spans.push_back(span);
}

}  // namespace isotrace
