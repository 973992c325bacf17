#pragma once
// Small operations on inside-span lists (see renderer/plugin/solid.h) that every solid needs: clipping a span to
// the query range, and pairing crossings into spans.
#include <optional>
#include <span>
#include <vector>

#include "renderer/plugin/solid.h"

namespace isotrace {

// Appends `span` clipped to [t_min, t_max]: an end beyond the range becomes a cut (BoundaryPoint::kCut) at the
// range's end; nothing is appended when the clipped span is empty.
void append_clipped_span(InsideSpan span, double t_min, double t_max, std::vector<InsideSpan>& spans);

// Pairs a solid's boundary crossings along a ray into inside spans, appended to `spans`. `crossings` are in
// increasing t within (t_min, t_max), each with `t` and `entering`; `inside_at_start` says whether the ray starts
// inside at t_min; surface_point(crossing) makes the crossing's BoundaryPoint. A crossing that repeats the
// current state (an entry while inside) is ignored; spans open at an end are cut there (BoundaryPoint::kCut).
template <class Crossing, class SurfacePoint>
void append_spans_from_crossings(std::span<const Crossing> crossings, bool inside_at_start, double t_min,
                                 double t_max, SurfacePoint&& surface_point, std::vector<InsideSpan>& spans) {
    const auto cut = [](double t) { return BoundaryPoint{t, {0, 0, 1}, BoundaryPoint::kCut, 0}; };
    std::optional<BoundaryPoint> open;
    if (inside_at_start) open = cut(t_min);
    for (const Crossing& crossing : crossings) {
        if (crossing.entering && !open) {
            open = surface_point(crossing);
        } else if (!crossing.entering && open) {
            if (crossing.t > open->t) spans.push_back({*open, surface_point(crossing)});
            open.reset();
        }
    }
    if (open && t_max > open->t) spans.push_back({*open, cut(t_max)});
}

}  // namespace isotrace
