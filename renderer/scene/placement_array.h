#pragma once
// PlacementArray: one shape, in its own space, placed many times — the copies of a definition's shape, or a single
// object whose transform its shape cannot bake. Embree sees one user geometry whose primitives are the placements:
// a primitive's box is the box of the shape's Embree scene carried to the world, and its callbacks carry the ray
// into the placement's space and trace that scene there (built once, shared by every placement). A placement keeps
// a PlacementRecord and its share of Embree's BVH over the placements; the rest is computed when a ray needs it.
#include <embree3/rtcore.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renderer/math/transform.h"
#include "renderer/plugin/placement_record.h"
#include "renderer/plugin/scene_object.h"

namespace isotrace {

// The names of the copies an instancing object places: "<object>[<index>]", unless the scene file names a copy, then
// "/<part>" for a part of a group.
struct PlacementNames {
    std::string object;
    std::string part_suffix;                                  // "/<part>" or ""
    std::vector<std::pair<std::uint32_t, std::string>> own;  // by increasing index: copies not named by default

    std::string default_name(std::uint32_t placement) const;
    std::string of(std::uint32_t placement) const;
};

class PlacementArray {
public:
    // `variants`: the objects the copies show (their materials; not owned, kept alive by the caller), each with the
    // shared shape and an identity to_world.
    PlacementArray(std::shared_ptr<Shape> shape, std::vector<const SceneObject*> variants,
                   std::vector<PlacementRecord> records, PlacementNames names);

    // The committed user geometry of the placements; `shape_scene` (committed, owned by the caller) holds the shape.
    RTCGeometry create_geometry(RTCDevice device, RTCScene shape_scene);

    Shape& shape() const { return *shape_; }
    const PlacementNames& names() const { return names_; }
    std::uint32_t size() const { return std::uint32_t(records_.size()); }
    const std::vector<const SceneObject*>& variants() const { return variants_; }
    const SceneObject& variant_of(std::uint32_t placement) const { return *variants_[records_[placement].variant]; }
    const PlacementRecord& record(std::uint32_t placement) const { return records_[placement]; }
    Transform to_world(std::uint32_t placement) const { return to_world_of_record(records_[placement]); }
    // Placement `placement` as an object of its own (for tools and tests: it copies its name and materials).
    SceneObject copy(std::uint32_t placement) const;
    // What the array keeps besides Embree's BVH and its variants.
    std::size_t memory_bytes() const;

private:
    static void bounds(const RTCBoundsFunctionArguments* args);
    static void intersect(const RTCIntersectFunctionNArguments* args);
    static void occluded(const RTCOccludedFunctionNArguments* args);

    std::shared_ptr<Shape> shape_;
    std::vector<const SceneObject*> variants_;
    std::vector<PlacementRecord> records_;
    PlacementNames names_;
    RTCScene shape_scene_ = nullptr;
    Bounds3f shape_scene_bounds_;  // Embree's bounds of shape_scene_, in the shape's space
};

}  // namespace isotrace
