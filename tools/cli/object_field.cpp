#include "tools/cli/object_field.h"

#include <stdexcept>

#include "geometry/field/transformed_field.h"
#include "renderer/core/did_you_mean.h"
#include "renderer/core/input_error.h"

namespace isotrace::cli {

std::string joined_names(const std::vector<std::string>& names) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    return list;
}

SceneObject find_object(const RenderScene& scene, const std::string& name, const std::string& file) {
    std::vector<std::string> names;
    for (std::uint32_t id = 0; id < scene.object_count(); ++id) {
        SceneObject object = scene.object(id);
        if (object.name == name) return object;
        names.push_back(object.name);
    }
    throw InputError({}, "--object",
                     "no object \"" + name + "\" in " + file + did_you_mean(name, names) + "; objects: " + joined_names(names));
}

std::unique_ptr<ImplicitField> placed(const SceneObject& object, std::unique_ptr<ImplicitField> field) {
    return object.instanced ? transformed_field(std::move(field), object.to_world) : std::move(field);
}

std::unique_ptr<ImplicitField> field_of(const SceneObject& object) {
    std::unique_ptr<ImplicitField> field;
    try {
        field = object.shape->implicit_field();
    } catch (const std::invalid_argument& error) {
        throw InputError({}, "--object", "object \"" + object.name + "\": " + error.what());
    }
    if (!field)
        throw InputError({}, "--object", "object \"" + object.name + "\" is a \"" + object.shape->type_name() +
                                             "\", which is not an implicit surface (objects traced as triangles: "
                                             "--method traced)");
    return placed(object, std::move(field));
}

}  // namespace isotrace::cli
