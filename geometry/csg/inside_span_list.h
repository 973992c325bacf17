#pragma once
// Small operations on inside-span lists (see renderer/plugin/solid.h) that every solid needs: clipping a span to
// the query range, and finding the surface point a ray meets first.
#include <optional>
#include <span>
#include <vector>

#include "renderer/plugin/solid.h"

namespace isotrace {

// Appends `span` clipped to [t_min, t_max]: an end beyond the range becomes a cut (BoundaryPoint::kCut) at the
// range's end; nothing is appended when the clipped span is empty.
void append_clipped_span(InsideSpan span, double t_min, double t_max, std::vector<InsideSpan>& spans);

// The first end of `spans` (in increasing t) that lies on the surface strictly inside (t_near, t_far).
std::optional<BoundaryPoint> first_surface_crossing(std::span<const InsideSpan> spans, double t_near, double t_far);

}  // namespace isotrace
