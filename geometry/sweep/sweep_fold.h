#pragma once
// Whether a sweep still bounds a volume that eq. (8) maps one to one: its cross-sections, in order along the
// axis, must follow each other without crossing. Two neighbouring sections cross when part of the later one lies
// behind the earlier one's plane (or the earlier one beyond the later one's): the axis turned back (sections out
// of order) or bent tighter than the section's radius (the inner side folds). Checked at `kFoldSamplesPerKey`
// sections per key interval and the sweep's radius sample angles.
#include <string>

namespace isotrace {

class SweepSurface;

inline constexpr int kFoldSamplesPerKey = 16;

// Empty when the sections follow each other; otherwise "sections at t = 0.41 and 0.42 cross".
std::string sweep_fold(const SweepSurface& sweep);

// The largest factor by which a length of `original` changed in `edited` (same key count and parameters), either
// way (≥ 1): the axis between neighbouring sample sections and each key's radii.
double sweep_stretch(const SweepSurface& original, const SweepSurface& edited);

}  // namespace isotrace
