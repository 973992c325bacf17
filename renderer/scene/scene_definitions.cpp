#include "renderer/scene/scene_definitions.h"

#include <algorithm>
#include <map>

#include "renderer/core/did_you_mean.h"
#include "renderer/params/transform_parser.h"
#include "renderer/params/world_limit.h"
#include "renderer/scene/instance_placements.h"
#include "renderer/scene/object_builder.h"

namespace isotrace {
namespace {

const char* const kShapeAndInstance = "an object has a \"shape\" or places an \"instance\", not both";

std::string chain_text(const std::vector<std::string>& chain, const std::string& last) {
    std::string text;
    for (const std::string& name : chain) text += name + " -> ";
    return text + last;
}

// A copy of `part` with its materials: the part's own, or `override`, which paints the whole copy (the parts' own
// materials give way). `name` is the copy's, for messages.
SceneObject painted(const SceneObject& part, const Material* override, const std::string& name) {
    SceneObject copy;
    copy.name = name;
    copy.shape = part.shape;
    if (override) {
        copy.material = override;
        check_texture_needs(copy);
    } else {
        copy.material = part.material;
        copy.part_materials = part.part_materials;
        copy.blended_material = part.blended_material;
    }
    return copy;
}

// Where `part` goes at `placement`; fails at the placement when that lies beyond the world.
Transform placed_part(const SceneNode& node, const Placement& placement, const SceneObject& part) {
    Transform to_world = placement.to_world * part.to_world;
    if (!placed_within_world(*part.shape, to_world))
        fail_at_placement(node, placement, beyond_world_problem("the shape, transformed,"));
    return to_world;
}

std::string part_suffix(const SceneObject& part) { return part.name.empty() ? "" : "/" + part.name; }

}  // namespace

SceneDefinitions::SceneDefinitions(std::optional<SceneNode> definitions, const SceneOverrides& overrides,
                                   RenderScene& scene)
    : overrides_(overrides), scene_(scene) {
    if (!definitions) return;
    definitions->accept_all_keys();
    for (const std::string& name : definitions->keys()) {
        definitions_.emplace(name, Definition{definitions->object(name), std::nullopt});
        names_.push_back(name);
    }
}

void SceneDefinitions::place(const SceneNode& node, const std::string& name) {
    const std::vector<SceneObject>& parts = parts_of(node);
    const std::vector<Placement> placements = read_placements(node, name, parts.size(), scene_);
    // Part by part: each part's copies are one array of placements.
    for (const SceneObject& part : parts) {
        Placements copies;
        copies.shape = part.shape;
        copies.names.object = name;
        copies.names.part_suffix = part_suffix(part);
        copies.records.reserve(placements.size());
        std::map<const Material*, std::uint32_t> variant_of_override;
        for (std::size_t i = 0; i < placements.size(); ++i) {
            const Placement& placement = placements[i];
            const Transform to_world = placed_part(node, placement, part);
            const auto [variant, added] =
                variant_of_override.try_emplace(placement.material, std::uint32_t(copies.variants.size()));
            if (added)
                copies.variants.push_back(painted(part, placement.material, placement.name + copies.names.part_suffix));
            const std::optional<PlacementRecord> record = placement_record(to_world, variant->second);
            if (!record) fail_at_placement(node, placement, kSingularInSinglePrecision);
            copies.records.push_back(*record);
            if (placement.name != copies.names.default_name(std::uint32_t(i)))
                copies.names.own.emplace_back(std::uint32_t(i), placement.name);
        }
        scene_.add_placements(std::move(copies));
    }
}

const std::vector<SceneObject>& SceneDefinitions::parts_of(const SceneNode& node) {
    if (node.has("shape")) node.fail_at("shape", kShapeAndInstance);
    const auto reference = node.optional_value("instance");
    if (!reference->json().is_string()) reference->fail("expected the name of a definition");
    const std::string& name = reference->json().string;
    const auto found = definitions_.find(name);
    if (found == definitions_.end())
        reference->fail("unknown definition \"" + name + "\"" + did_you_mean(name, names_) +
                        (names_.empty() ? "; the scene has no \"definitions\"" : ""));
    if (std::find(resolving_.begin(), resolving_.end(), name) != resolving_.end())
        reference->fail("definition \"" + name + "\" places itself: " + chain_text(resolving_, name));
    if (resolving_.size() >= std::size_t(kMaxDefinitionDepth))
        reference->fail("definitions nest more than " + std::to_string(kMaxDefinitionDepth) +
                        " deep: " + chain_text(resolving_, name));
    Definition& definition = found->second;
    if (!definition.parts) {
        resolving_.push_back(name);
        definition.parts = build(name, definition.node);
        resolving_.pop_back();
    }
    return *definition.parts;
}

std::vector<SceneObject> SceneDefinitions::build(const std::string& name, const SceneNode& definition) {
    std::vector<SceneObject> parts;
    const auto add_shape = [&](const SceneNode& node, const std::string& part_name) {
        SceneObject part = build_shaped_object(node, part_name, overrides_, scene_);
        part.to_world = parse_optional_transform(node, "transform");
        // The shape is shared by every placement: it keeps statistics under the definition's name.
        part.shape->set_object_name(part_name.empty() ? name : name + "/" + part_name);
        node.finish();
        parts.push_back(std::move(part));
    };
    if (definition.has("shape") == definition.has("objects"))
        definition.fail("a definition has a \"shape\" (with its \"material\") or \"objects\" (a group), one of the two");
    if (definition.has("shape")) {
        add_shape(definition, "");
        return parts;
    }
    const std::vector<SceneNode> members = definition.object_array("objects");
    if (members.empty()) definition.fail_at("objects", "a group needs at least one object");
    for (std::size_t i = 0; i < members.size(); ++i) {
        const SceneNode& member = members[i];
        const std::string member_name = member.string_or("name", "objects[" + std::to_string(i) + "]");
        if (!member.has("instance")) {
            add_shape(member, member_name);
            continue;
        }
        const std::vector<SceneObject>& inner = parts_of(member);
        for (const Placement& placement : read_placements(member, member_name, inner.size(), scene_))
            for (const SceneObject& part : inner) {
                if (parts.size() >= kMaxPlacedObjects)
                    member.fail("the group \"" + name + "\" has more than " + std::to_string(kMaxPlacedObjects) +
                                " parts");
                SceneObject placed = painted(part, placement.material, placement.name + part_suffix(part));
                placed.to_world = placed_part(member, placement, part);
                parts.push_back(std::move(placed));
            }
        member.finish();
    }
    definition.finish();
    return parts;
}

}  // namespace isotrace
