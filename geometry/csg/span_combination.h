#pragma once
// Roth's ray classification ("Ray Casting for Modeling Solids", 1982): the inside spans of a union, intersection
// or difference follow from the operands' inside spans alone. Every span end becomes an event; a sweep in t keeps
// how many operands the ray is inside and emits a boundary wherever the combined membership changes.
//
// Coincident surfaces: events whose t agree to kCoincidentRelative·|t| happen at once (their t was computed by
// different code for the same point), and so do events within the precision either end reports
// (BoundaryPoint::t_tolerance: a float mesh's). So A − A and A ∩ ¬A are empty, A ∪ A and A ∩ A are A, and solids
// of a union that touch merge into one span (no surface inside the union). The relative tolerance is far below the
// float precision of the t that Embree reports, so no visible surface moves.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "renderer/plugin/solid.h"

namespace isotrace {

enum class CsgOperation {
    Union,
    Intersection,
    Difference,  // the first operand minus all others
};

// One end of one operand's inside span.
struct SpanEvent {
    BoundaryPoint point;
    std::uint32_t operand = 0;
    bool enters = false;
};

inline constexpr double kCoincidentRelative = 1e-9;

// How far from `end` another operand's surface is still the same surface: the relative tolerance, or the precision
// the end was found with, whichever is larger.
inline double coincidence_tolerance(const BoundaryPoint& end) {
    return std::max(kCoincidentRelative * std::abs(end.t), end.t_tolerance);
}

// Appends the events of `spans`, the inside spans of operand `operand`, with `part_offset` added to their parts.
void append_span_events(std::uint32_t operand, std::uint32_t part_offset, const std::vector<InsideSpan>& spans,
                        std::vector<SpanEvent>& events);

// Sorts `events` (of `operand_count` operands, each with disjoint spans) and appends the inside spans of their
// combination to `result`. A result end is the operand end that caused the change, with the normal flipped when
// the operand is subtracted (the result's outside is the subtracted solid's inside there).
void combine_span_events(CsgOperation operation, std::uint32_t operand_count, std::vector<SpanEvent>& events,
                         std::vector<InsideSpan>& result);

}  // namespace isotrace
