#pragma once
// SceneObject: a shape placed in the scene with its materials, as the scene holds it and a hit refers to it
// (SurfaceHit::object), so that textures, materials and integrators can read the object they shade.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "renderer/math/transform.h"
#include "renderer/plugin/light_choice.h"
#include "renderer/plugin/shape.h"

namespace isotrace {

class Material;

struct SceneObject {
    std::string name;
    std::shared_ptr<Shape> shape;  // shared by the placements of one definition (RenderScene::add_placements)
    const Material* material = nullptr;
    std::vector<const Material*> part_materials;  // per Shape::part_materials() entry; null: `material`
    const Material* blended_material = nullptr;   // for shapes whose hits blend their parts' materials
    Transform to_world;
    bool instanced = false;  // true: the shape stays in object space, traced as a placement (PlacementArray)
    HitShading hit_shading = HitShading::Computed;  // the shape's, after any bake (set by commit)
    TriangleView triangles;  // the shape's embree_triangles(), after any bake (set by commit)
    int counter_slot = 0;
    LightChoice area_light;  // set when the object emits and its surface can be sampled

    const Material* material_of_part(std::uint32_t part) const {
        return part < part_materials.size() && part_materials[part] ? part_materials[part] : material;
    }
};

}  // namespace isotrace
