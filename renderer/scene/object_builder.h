#pragma once
// What a scene object shows, read from its JSON: the shape (with any shape wrappers), the material and the
// materials of the shape's parts, each checked against the shape. Plain objects and the shapes of definitions
// (scene_definitions.h) are read by the same code.
#include <string>

#include "renderer/math/transform.h"
#include "renderer/params/scene_node.h"
#include "renderer/plugin/scene_object.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {

// node["material"]: a name from "materials" or an inline material (added to the scene). Fails when it is missing.
const Material* resolve_material(const SceneNode& node, RenderScene& scene);
// A material value (a name or an inline material object) at `value`.
const Material* material_of_value(const SceneNode& value, RenderScene& scene);

// The object `name` with the shape of node["shape"], node's wrappers and its materials; its transform is left to
// the caller. Fails at node["shape"] when the shape reaches beyond the world in its own space.
SceneObject build_shaped_object(const SceneNode& node, const std::string& name, const SceneOverrides& overrides,
                                RenderScene& scene);

// False when `to_world` moves or scales the shape beyond the world (beyond_world_problem("the shape,
// transformed,") says so).
bool placed_within_world(const Shape& shape, const Transform& to_world);

// A texture mapped by uv needs a surface with uv, a field input a surface with a field.
void check_texture_needs(const SceneObject& object);

}  // namespace isotrace
