#pragma once
// SceneDefinitions: the scene's "definitions" — named shapes and groups of objects that instancing objects place
// many times (docs/scene-format.md, "Instances"). A definition is read on its first use and its shapes are built
// once: every placement shares them, each part's copies one array of placements (RenderScene::add_placements).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "renderer/params/scene_node.h"
#include "renderer/plugin/scene_object.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {

// Definitions nest (a group placing another definition) at most this deep.
constexpr int kMaxDefinitionDepth = 16;

class SceneDefinitions {
public:
    // `definitions`: the scene's "definitions" object, when it has one.
    SceneDefinitions(std::optional<SceneNode> definitions, const SceneOverrides& overrides, RenderScene& scene);

    // Adds to the scene the copies that the top-level instancing object `node` (one with "instance") places, named
    // after `name`: for each part of its definition, one array of placements. Fails at the position of what is wrong.
    void place(const SceneNode& node, const std::string& name);

private:
    struct Definition {
        SceneNode node;
        std::optional<std::vector<SceneObject>> parts;  // in the definition's space; built on first use
    };

    const std::vector<SceneObject>& parts_of(const SceneNode& node);
    std::vector<SceneObject> build(const std::string& name, const SceneNode& definition);

    const SceneOverrides& overrides_;
    RenderScene& scene_;
    std::map<std::string, Definition> definitions_;
    std::vector<std::string> names_;
    std::vector<std::string> resolving_;  // the definitions being built, outermost first: a cycle's chain
};

}  // namespace isotrace
