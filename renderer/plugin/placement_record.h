#pragma once
// PlacementRecord: where a copy of a shape traced in its own space is placed, in the 52 bytes a placement keeps
// (renderer/scene/placement_array.h), and the transform computed from it for shading.
#include <array>
#include <cstdint>
#include <optional>

#include "renderer/math/transform.h"

namespace isotrace {

struct PlacementRecord {
    // World to the shape's space, row-major 3x4, in single precision as Embree's instances held it: what a ray is
    // carried by. Its double-precision inverse is the placement's to_world for shading (to_world_of_record).
    std::array<float, 12> from_world;
    std::uint32_t variant = 0;  // which of the array's objects (the materials a copy shows)
};

// Why placement_record failed, for the message at the transform.
inline constexpr const char* kSingularInSinglePrecision =
    "the transform is singular once rounded to single precision (in which rays are carried into the shape's space)";

// The record of a placement at `to_world`; nullopt when that transform, rounded to single precision, is singular.
std::optional<PlacementRecord> placement_record(const Transform& to_world, std::uint32_t variant);
// The record's placement, in double precision (deterministic: every hit on it gets the same bits).
Transform to_world_of_record(const PlacementRecord& record);

}  // namespace isotrace
