#pragma once
// What a ray query of a blob group finds: a sign change of the summed field F along the ray, and for the nearest
// hit the outward normal there.
#include <cmath>
#include <cstdint>
#include <optional>

#include "renderer/math/vec3.h"

namespace isotrace {

// A sign change of F: entering the surface (F becomes > 0) or leaving it.
struct FieldCrossing {
    double t = 0;
    bool entering = false;
    std::uint32_t element = 0;  // an element whose support contains the crossing
};

// A cell's first crossing, with the outward unit normal at the point where a renderer places it.
struct CellHit {
    FieldCrossing crossing;
    // At o + d·float(t) (Embree keeps a hit's t as a float, and the shading point is computed from it); std::nullopt
    // where −∇F vanishes there (a hard cube's face: BlobGroup::normal_in_cell takes the face's normal).
    std::optional<Vec3d> normal;
};

// −g/|g|, the outward unit normal of F = 0 for g = ∇(F + T); std::nullopt where g vanishes (only on a hard cube's
// face, where F steps) or overflows.
inline std::optional<Vec3d> outward_normal(const Vec3d& gradient) {
    const double len = length(gradient);
    if (len > 0 && std::isfinite(len)) return -gradient / len;
    return std::nullopt;
}

}  // namespace isotrace
