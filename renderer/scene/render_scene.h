#pragma once
// RenderScene: the committed, ready-to-trace scene. Owns the plugins created from the scene file and the
// Embree scene that holds their geometry; answers nearest-hit and occlusion queries.
#include <embree3/rtcore.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/core/ray.h"
#include "renderer/core/render_counters.h"
#include "renderer/math/transform.h"
#include "renderer/plugin/light.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/shape.h"
#include "renderer/scene/surface_hit.h"

namespace isotrace {

struct SceneObject {
    std::string name;
    std::unique_ptr<Shape> shape;
    const Material* material = nullptr;
    Transform to_world;
    bool instanced = false;  // true: shape in object space inside an Embree instance
    int counter_slot = 0;
};

struct BuildStatistics {
    double seconds = 0;
    std::size_t objects = 0;
    std::size_t instanced_objects = 0;
    std::map<std::string, std::size_t> primitives_by_type;
    std::int64_t embree_bytes = 0;
};

class RenderScene {
public:
    RenderScene();
    ~RenderScene();
    RenderScene(const RenderScene&) = delete;
    RenderScene& operator=(const RenderScene&) = delete;

    // Scene assembly (before commit).
    const Material* add_material(const std::string& name, std::unique_ptr<Material> material);
    const Material* find_material(const std::string& name) const;
    std::vector<std::string> material_names() const;
    void add_object(SceneObject object);
    void add_light(std::unique_ptr<Light> light);

    // Builds the Embree BVHs. Throws std::runtime_error on Embree errors.
    void commit();

    std::optional<SurfaceHit> intersect(const Ray& ray, RayKind kind) const;
    bool occluded(const Ray& ray) const;

    const std::vector<SceneObject>& objects() const { return objects_; }
    const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }
    const BuildStatistics& build_statistics() const { return build_statistics_; }
    Bounds3f bounds() const;

private:
    RTCScene scene_ = nullptr;
    std::vector<RTCScene> instance_scenes_;
    std::vector<SceneObject> objects_;
    std::vector<std::uint32_t> object_of_geometry_;  // top-level geometry id -> object index
    std::map<std::string, std::unique_ptr<Material>> materials_;
    std::vector<std::unique_ptr<Light>> lights_;
    BuildStatistics build_statistics_;
};

}  // namespace isotrace
