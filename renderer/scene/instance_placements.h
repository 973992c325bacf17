#pragma once
// The placements an instancing object asks for (docs/scene-format.md, "Instances"): itself once, each entry of its
// "placements", or every cell of its "grid" — each under the object's own "transform" and material override.
#include <cstddef>
#include <string>
#include <vector>

#include "renderer/math/transform.h"
#include "renderer/params/scene_node.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {

// The most placements one object may ask for, and the most objects the placements of a scene may add (a group
// definition places all of its parts at every placement).
constexpr std::size_t kMaxPlacementsPerObject = std::size_t(1) << 22;
constexpr std::size_t kMaxPlacedObjects = std::size_t(1) << 24;

struct Placement {
    std::string name;
    Transform to_world;                 // the instancing object's transform times the placement's own
    const Material* material = nullptr; // replaces the definition's materials; null keeps them
    std::size_t entry = kNoEntry;       // its index in the object's "placements"; kNoEntry for a grid or one copy
    static constexpr std::size_t kNoEntry = std::size_t(-1);
};

// Fails where the placement is written: its entry's "transform" (or the entry) in "placements", else the object's
// "grid" or "transform".
[[noreturn]] void fail_at_placement(const SceneNode& node, const Placement& placement, const std::string& problem);

// Reads node's "transform", "material", and "placements" or "grid"; placements are named `name` when the object
// places once, else "<name>[<index>]" unless they have a name of their own. Each placement adds `parts` objects to
// the scene: their count is bounded and their memory charged before any is made.
std::vector<Placement> read_placements(const SceneNode& node, const std::string& name, std::size_t parts,
                                       RenderScene& scene);

}  // namespace isotrace
