#pragma once
// RenderScene: the committed, ready-to-trace scene. Owns the plugins created from the scene file and the
// Embree scene that holds their geometry; answers nearest-hit and occlusion queries.
#include <embree3/rtcore.h>

#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "renderer/embree/inner_root.h"
#include "renderer/core/ray.h"
#include "renderer/core/render_counters.h"
#include "renderer/embree/embree_ray.h"
#include "renderer/embree/query_context.h"
#include "renderer/math/transform.h"
#include "renderer/plugin/light.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/scene_object.h"
#include "renderer/plugin/shape.h"
#include "renderer/plugin/surface_hit.h"
#include "renderer/sampling/distribution_1d.h"
#include "renderer/scene/placement_array.h"

namespace isotrace {

struct BuildStatistics {
    double seconds = 0;
    std::size_t objects = 0;
    // Traced in their shape's space: placements, and objects whose transform cannot bake.
    std::size_t instanced_objects = 0;
    std::size_t placements = 0;         // copies of a definition's shapes (add_placements)
    std::size_t placed_shapes = 0;      // the shapes they share, each built once
    std::map<std::string, std::size_t> primitives_by_type;  // each shape counted once, however often placed
    std::int64_t embree_bytes = 0;
    std::size_t shape_bytes = 0;  // what the shapes keep besides Embree's buffers and BVHs, each shape once
    std::size_t object_bytes = 0;  // what the scene keeps per object (SceneObject, its name and part materials; a
                                   // placement's record)
    std::size_t area_lights = 0;
    // Emissive objects that light sampling cannot reach (shapes without surface sampling): they still emit when
    // BSDF sampling hits them.
    std::size_t unsampled_emitters = 0;
};

// The copies of one shape that an instancing object places (renderer/scene/scene_definitions.h), as
// RenderScene::add_placements takes them.
struct Placements {
    std::shared_ptr<Shape> shape;         // shared with other placements of the same definition
    std::vector<SceneObject> variants;    // the materials the copies show; shape set, to_world identity, no name
    std::vector<PlacementRecord> records;  // one per copy
    PlacementNames names;
};

class RenderScene {
public:
    // From this many placements on, their BVH is built for memory rather than speed (RTC_BUILD_QUALITY_LOW: about 24
    // bytes per placement instead of 120, and about 6 % slower to trace).
    static constexpr std::size_t kPlacementsBuiltCompactly = 4096;

    RenderScene();
    ~RenderScene();
    RenderScene(const RenderScene&) = delete;
    RenderScene& operator=(const RenderScene&) = delete;

    // Scene assembly (before commit).
    const Material* add_material(const std::string& name, std::unique_ptr<Material> material);
    const Material* find_material(const std::string& name) const;
    std::vector<std::string> material_names() const;
    void add_object(SceneObject object);
    // Copies of a shape shared with other placements (a definition's, renderer/scene/scene_definitions.h): the shape
    // stays in its own space, built once into one Embree scene, and the copies are the primitives of one
    // PlacementArray. An emissive placement whose shape can sample its surface is an area light of its own, as
    // the same object written out separately is.
    void add_placements(Placements placements);
    void add_light(std::unique_ptr<Light> light);

    // Builds the Embree BVHs. Throws std::runtime_error on Embree errors.
    void commit();

    std::optional<SurfaceHit> intersect(const Ray& ray, RayKind kind) const;
    // Up to eight rays (found.size() >= rays.size() <= 8) as one Embree packet query, for the lanes whose bit is set
    // in `live`: found[lane] is what intersect(rays[lane], kind) gives, bit for bit; the other lanes' are reset. User
    // geometries answer the packet lane by lane.
    void intersect(std::span<const Ray> rays, unsigned live, RayKind kind,
                   std::span<std::optional<SurfaceHit>> found) const;
    // The lanes of `live` whose shadow rays occluded(rays[lane]) finds blocked, as one packet query.
    unsigned occluded(std::span<const Ray> rays, unsigned live) const;
    // The hit's position error bound is this times (the largest |coordinate| of the hit + t |direction|).
    static constexpr float kPositionErrorScale = 64.0f * std::numeric_limits<float>::epsilon();
    // Inline: the path tracer builds a shadow ray just before asking, and through a call the ray went to memory
    // field by field and came back in the 16-byte loads that build Embree's ray, each waiting for those stores.
    // A ray Embree cannot trace (is_traceable, renderer/embree/embree_ray.h) misses, and a shadow ray of that kind
    // is blocked: no light arrives along it. Both are counted (count_untraceable_rays).
    bool occluded(const Ray& ray) const {
        counters::count_ray(RayKind::Shadow);
        if (!is_traceable(ray)) [[unlikely]] {
            count_untraceable_rays(1);
            return true;
        }
        // Two passes (OcclusionPass): the queries a primitive puts off are asked only when nothing else blocks.
        QueryContext context(scratch_pool_);
        context.occlusion_pass = OcclusionPass::AwayFromStarts;
        RTCRay query;
        set_embree_ray(query, ray);
        context.rays = &query, context.ray_count = 1;
        rtcOccluded1(scene_, &context.embree, &query);
        constexpr float kBlocked = -std::numeric_limits<float>::infinity();
        if (query.tfar == kBlocked) return true;
        if (!context.put_off.any()) return false;
        if (context.put_off.all_kept()) return context.put_off.ask(1u) != 0;
        context.occlusion_pass = OcclusionPass::AtStarts;
        rtcOccluded1(scene_, &context.embree, &query);  // a ray nothing blocked is as it was
        return query.tfar == kBlocked;
    }

    // Lights in proportion to their power (all lights: scene-file lights and area lights).
    LightChoice choose_light(float u) const;
    const std::vector<LightChoice>& infinite_lights() const { return infinite_lights_; }
    const std::vector<const Light*>& all_lights() const { return all_lights_; }
    // False when no ray can gather emission by hitting something (only delta lights: no emissive surface, no
    // environment): a path's last ray, which would only look for emission, need not be traced.
    bool emission_can_be_hit() const { return emission_can_be_hit_; }
    // True when choosing and sampling a light reads no random number: at most one light, and that a delta light.
    bool light_sampling_is_deterministic() const { return light_sampling_is_deterministic_; }


    // The objects written with a shape of their own (add_object), in the order added; placements are not among them.
    const std::vector<SceneObject>& objects() const { return objects_; }
    // Every object, placements included, by the id that hits report (SurfaceHit::object_index): ids follow the order
    // objects and placements were added. object(id) is a copy (for tools and tests, not for every ray).
    std::uint32_t object_count() const { return next_id_; }
    SceneObject object(std::uint32_t id) const;
    // The id of the object Embree knows as top-level geometry `id`, for scenes without placements.
    std::uint32_t object_of_geometry(unsigned id) const { return traced_[id].id; }
    const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }
    const BuildStatistics& build_statistics() const { return build_statistics_; }
    // The scene's extent: Embree's bounds of the whole scene, without unbounded shapes (Shape::is_unbounded) when
    // there are any.
    Bounds3f bounds() const;

    // The "rays.untraceable" counter: rays answered without Embree.
    static void count_untraceable_rays(std::uint64_t count);

private:
    // What a top-level Embree geometry is: an object of objects_ traced in world space, or an array of placements.
    struct TracedGeometry {
        const SceneObject* object = nullptr;
        const PlacementArray* placements = nullptr;
        std::uint32_t id = 0;  // the object's id; the first placement's for an array
    };
    // The ids of an object of objects_ (one) or of an array of placed_ (one per placement), in the order added.
    struct IdRange {
        std::uint32_t first_id = 0;
        std::uint32_t index = 0;  // in objects_ or placed_
        bool placed = false;
    };

    RTCScene scene_ = nullptr;
    std::vector<RTCScene> shape_scenes_;  // the Embree scenes that placement arrays trace in, and theirs
    InnerRootSentinel scene_sentinel_, placements_sentinel_;  // for a lone user primitive or placement
    std::vector<SceneObject> objects_;
    std::deque<SceneObject> placement_variants_;         // the objects that placements show (stable addresses)
    std::vector<std::unique_ptr<PlacementArray>> placed_;  // add_placements' arrays, in the order added
    std::vector<std::unique_ptr<PlacementArray>> single_placements_;  // objects whose transform cannot bake
    // The emissive placements that are area lights, by increasing object id: each shows an object of its own in
    // placement_variants_, which holds its light.
    struct EmissivePlacement {
        const PlacementArray* array;
        std::uint32_t placement;
        SceneObject* object;
    };
    std::vector<EmissivePlacement> emissive_placements_;
    std::vector<TracedGeometry> traced_;  // by top-level geometry id
    std::vector<IdRange> id_ranges_;      // by increasing first_id
    std::uint32_t next_id_ = 0;
    std::map<std::string, std::unique_ptr<Material>> materials_;
    std::vector<std::unique_ptr<Light>> lights_;  // scene-file lights, then area lights
    std::vector<const Light*> all_lights_;
    std::vector<LightChoice> infinite_lights_;
    std::unique_ptr<Distribution1D> light_distribution_;
    bool emission_can_be_hit_ = false;
    bool light_sampling_is_deterministic_ = true;
    BuildStatistics build_statistics_;
    // The buffers of queries that reach solids (CSG, superquadrics, ...), lent to them through QueryContext.
    mutable QueryScratchPool scratch_pool_;

    // The SurfaceHit of Embree's hit at distance t along `ray` (a triangle hit's t, u, v and Ng solved again).
    void complete_hit(const Ray& ray, const RTCHit& found_hit, float t, std::optional<SurfaceHit>& found) const;
    RTCScene new_shape_scene(RTCGeometry geometry);
    void attach(RTCGeometry geometry, const TracedGeometry& traced, const std::string& name);
    void build_lights();
};

}  // namespace isotrace
