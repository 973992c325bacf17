#include "renderer/scene/object_builder.h"

#include "renderer/core/did_you_mean.h"
#include "renderer/materials/blended_material.h"
#include "renderer/math/box_corner.h"
#include "renderer/params/world_limit.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/shape.h"

namespace isotrace {
namespace {

std::string unknown_material_problem(const std::string& name, const RenderScene& scene) {
    std::string known;
    for (const auto& n : scene.material_names())
        if (n.front() != '<') known += (known.empty() ? "" : ", ") + n;
    return "unknown material \"" + name + "\"" + did_you_mean(name, scene.material_names()) +
           (known.empty() ? "; the scene defines no materials" : "; defined: " + known);
}

// The materials the parts of a composite shape name (null where a part names none).
std::vector<const Material*> resolve_part_materials(const Shape& shape, const RenderScene& scene) {
    std::vector<const Material*> materials;
    for (const MaterialReference& reference : shape.part_materials()) {
        const Material* material = reference.name.empty() ? nullptr : scene.find_material(reference.name);
        if (!reference.name.empty() && !material)
            throw InputError(reference.location, reference.field, unknown_material_problem(reference.name, scene));
        materials.push_back(material);
    }
    return materials;
}

// The material of a shape whose parts blend: every part's material must be able to blend.
const Material* blended_material(const SceneNode& node, const SceneObject& object, RenderScene& scene) {
    const std::vector<MaterialReference> references = object.shape->part_materials();
    std::vector<const Material*> parts;
    for (std::size_t part = 0; part < object.part_materials.size(); ++part) {
        const Material* material = object.material_of_part(std::uint32_t(part));
        if (!material->can_blend()) {
            const std::string problem =
                "materials that blend across a surface must be \"principled\" or \"diffuse\"";
            if (object.part_materials[part]) throw InputError(references[part].location, references[part].field, problem);
            node.fail_at("material", problem + " (this object's material is used where its elements name none)");
        }
        parts.push_back(material);
    }
    return scene.add_material("<blended materials of " + node.path() + ">", make_blended_material(std::move(parts)));
}

template <class Corners>
bool corners_within_world(const Shape& shape, Corners corner_to_world) {
    const Bounds3f local = shape.bounds();
    // Unbounded shapes (the plane) reach the edge by definition: they are clipped to the world, not held inside it.
    if (local.empty() || shape.is_unbounded()) return true;
    const Vec3d lower(local.lower.x, local.lower.y, local.lower.z), upper(local.upper.x, local.upper.y, local.upper.z);
    for (int i = 0; i < 8; ++i)
        if (!within_world(corner_to_world(box_corner(lower, upper, i)))) return false;
    return true;
}

}  // namespace

const Material* material_of_value(const SceneNode& value, RenderScene& scene) {
    if (value.json().is_object())
        return scene.add_material("<inline material of " + value.path() + ">", material_registry().create(value));
    if (!value.json().is_string()) value.fail("expected a material name or an inline material object");
    const std::string& name = value.json().string;
    const Material* material = scene.find_material(name);
    if (!material) value.fail(unknown_material_problem(name, scene));
    return material;
}

const Material* resolve_material(const SceneNode& node, RenderScene& scene) {
    const auto value = node.optional_value("material");
    if (!value) node.fail("missing required field \"material\" (a name from \"materials\" or an inline material)");
    return material_of_value(*value, scene);
}

SceneObject build_shaped_object(const SceneNode& node, const std::string& name, const SceneOverrides& overrides,
                                RenderScene& scene) {
    SceneObject object;
    object.name = name;
    object.material = resolve_material(node, scene);
    std::unique_ptr<Shape> shape = shape_registry().create(node.object("shape"));
    for (const auto& [key, wrapper] : shape_wrapper_registry().entries())
        if (auto settings = node.optional_object(key)) shape = wrapper.factory(*settings, std::move(shape));
    if (overrides.replace_shape) shape = overrides.replace_shape(std::move(shape));
    // The shape's own parameters first (a tube radius, a vertex; shapes whose plugins check no extent), then its
    // placement (check_placement_within_world).
    if (!corners_within_world(*shape, [](const Vec3d& p) { return p; }))
        node.fail_at("shape", beyond_world_problem("the shape"));
    object.shape = std::move(shape);
    object.part_materials = resolve_part_materials(*object.shape, scene);
    if (object.shape->blends_parts()) object.blended_material = blended_material(node, object, scene);
    check_texture_needs(object);
    return object;
}

bool placed_within_world(const Shape& shape, const Transform& to_world) {
    return corners_within_world(shape, [&](const Vec3d& p) { return to_world.point(p); });
}

void check_texture_needs(const SceneObject& object) {
    TextureNeeds needs = object.material->texture_needs();
    for (const Material* part : object.part_materials)
        if (part) needs |= part->texture_needs();
    const Shape& shape = *object.shape;
    const std::string whose = "the shape of object \"" + object.name + "\" (" + shape.type_name() + ")";
    if (needs.uv && !shape.has_uv())
        throw InputError(needs.where, needs.field_path,
                         "this texture is mapped by uv, but " + whose +
                             " has no uv: use a \"solid\", \"planar\", \"triplanar\", \"spherical\" or "
                             "\"cylindrical\" projection");
    if (needs.field && !shape.field_value(Vec3d(0, 0, 0)))
        throw InputError(needs.where, needs.field_path,
                         "this texture reads a field, but " + whose + " has none (blob groups and superquadrics have one)");
}

}  // namespace isotrace
