#pragma once
// The implicit field of a scene object in world space, for the polygoniser (isotrace mesh, isotrace bench).
#include <memory>
#include <string>
#include <vector>

#include "renderer/plugin/implicit_field.h"
#include "renderer/scene/render_scene.h"

namespace isotrace::cli {

// "a, b, c": names for an error message.
std::string joined_names(const std::vector<std::string>& names);

// The object (or placed copy) called `name` in the scene read from `file`; throws InputError naming --object (with
// the names there are) when there is none.
SceneObject find_object(const RenderScene& scene, const std::string& name, const std::string& file);

// An object's field in world space (an instanced object's shape is in object space).
std::unique_ptr<ImplicitField> placed(const SceneObject& object, std::unique_ptr<ImplicitField> field);

// The object's field in world space; throws InputError naming --object when the shape is not an implicit surface.
std::unique_ptr<ImplicitField> field_of(const SceneObject& object);

}  // namespace isotrace::cli
