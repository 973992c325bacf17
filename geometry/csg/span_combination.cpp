#include "geometry/csg/span_combination.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace isotrace {
namespace {

// Which operands the ray is inside at some t; each operand contributes at most one span there.
struct Membership {
    std::uint32_t inside_count = 0;
    bool inside_first = false;

    void apply(const SpanEvent& event) {
        if (event.enters) {
            ++inside_count;
        } else {
            --inside_count;
        }
        if (event.operand == 0) inside_first = event.enters;
    }

    bool inside(CsgOperation operation, std::uint32_t operand_count) const {
        switch (operation) {
            case CsgOperation::Union: return inside_count > 0;
            case CsgOperation::Intersection: return inside_count == operand_count;
            case CsgOperation::Difference: return inside_first && inside_count == 1;
        }
        return false;
    }
};

bool subtracted(CsgOperation operation, std::uint32_t operand) {
    return operation == CsgOperation::Difference && operand > 0;
}

}  // namespace

void append_span_events(std::uint32_t operand, std::uint32_t part_offset, const std::vector<InsideSpan>& spans,
                        std::vector<SpanEvent>& events) {
    for (const InsideSpan& span : spans) {
        SpanEvent enter{span.enter, operand, true}, exit{span.exit, operand, false};
        enter.point.part += part_offset;
        exit.point.part += part_offset;
        events.push_back(enter);
        events.push_back(exit);
    }
}

void combine_span_events(CsgOperation operation, std::uint32_t operand_count, std::vector<SpanEvent>& events,
                         std::vector<InsideSpan>& result) {
    // Ties in t are broken by operand, then exits first, so the chosen boundary does not depend on sort order.
    std::sort(events.begin(), events.end(), [](const SpanEvent& a, const SpanEvent& b) {
        return std::tie(a.point.t, a.operand, a.enters) < std::tie(b.point.t, b.operand, b.enters);
    });
    Membership membership;
    bool inside = false;
    BoundaryPoint enter;
    for (std::size_t first = 0; first < events.size();) {
        // Simultaneous with the first event: within its coincidence tolerance or the later event's own.
        const BoundaryPoint& first_point = events[first].point;
        const auto simultaneous = [&](const BoundaryPoint& point) {
            return point.t - first_point.t <= std::max(coincidence_tolerance(first_point), point.t_tolerance);
        };
        std::size_t end = first;
        for (; end < events.size() && simultaneous(events[end].point); ++end) membership.apply(events[end]);
        const bool now_inside = membership.inside(operation, operand_count);
        if (now_inside != inside) {
            // The event that moves the result the same way: an operand entering (or a subtracted one exiting)
            // when the result is entered, the opposite when it is left. The operators are monotone in each
            // operand, so the group holds one. A surface is preferred to a cut end: a query range that starts or
            // ends a hair from a surface (CSG widens a later operand's range by the tolerance) must not hide it.
            const auto moves_result = [&](const SpanEvent& event) {
                return (event.enters != subtracted(operation, event.operand)) == now_inside;
            };
            std::size_t chosen = end;
            for (std::size_t k = first; k < end; ++k) {
                if (!moves_result(events[k])) continue;
                if (chosen == end) chosen = k;
                if (events[k].point.on_surface()) {
                    chosen = k;
                    break;
                }
            }
            if (chosen != end) {
                BoundaryPoint point = events[chosen].point;
                if (subtracted(operation, events[chosen].operand)) point.normal = -point.normal;
                if (now_inside) {
                    enter = point;
                } else {
                    result.push_back({enter, point});
                }
            }
            inside = now_inside;
        }
        first = end;
    }
}

}  // namespace isotrace
