#include "renderer/scene/render_scene.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "renderer/embree/embree_device.h"
#include "renderer/embree/embree_ray.h"
#include "renderer/lights/area_light.h"
#include "renderer/math/box_corner.h"
#include "renderer/math/lanes.h"
#include "renderer/math/lanes4.h"

namespace isotrace {
RenderScene::RenderScene() : scene_(rtcNewScene(embree_device())) { check_embree("creating the scene"); }

RenderScene::~RenderScene() {
    rtcReleaseScene(scene_);  // first: its geometries refer to the shape scenes
    for (RTCScene child : shape_scenes_) rtcReleaseScene(child);
}

const Material* RenderScene::add_material(const std::string& name, std::unique_ptr<Material> material) {
    auto& slot = materials_[name];
    slot = std::move(material);
    return slot.get();
}

const Material* RenderScene::find_material(const std::string& name) const {
    const auto found = materials_.find(name);
    return found == materials_.end() ? nullptr : found->second.get();
}

std::vector<std::string> RenderScene::material_names() const {
    std::vector<std::string> names;
    for (const auto& [name, material] : materials_) names.push_back(name);
    return names;
}

void RenderScene::add_object(SceneObject object) {
    id_ranges_.push_back({next_id_++, std::uint32_t(objects_.size()), false});
    objects_.push_back(std::move(object));
}

void RenderScene::add_placements(Placements placements) {
    std::vector<const SceneObject*> variants;
    for (SceneObject& variant : placements.variants) {
        placement_variants_.push_back(std::move(variant));
        variants.push_back(&placement_variants_.back());
    }
    // An emissive placement that is an area light shows an object of its own, whose area_light is its light.
    std::vector<std::pair<std::uint32_t, SceneObject*>> lit;
    if (placements.shape->supports_surface_sampling())
        for (std::uint32_t placement = 0; placement < placements.records.size(); ++placement) {
            PlacementRecord& record = placements.records[placement];
            const SceneObject& shown = *variants[record.variant];
            if (!shown.material || !shown.material->is_emissive()) continue;
            placement_variants_.push_back(shown);
            record.variant = std::uint32_t(variants.size());
            variants.push_back(&placement_variants_.back());
            lit.emplace_back(placement, &placement_variants_.back());
        }
    const auto count = std::uint32_t(placements.records.size());
    placed_.push_back(std::make_unique<PlacementArray>(std::move(placements.shape), std::move(variants),
                                                       std::move(placements.records), std::move(placements.names)));
    for (const auto& [placement, object] : lit) emissive_placements_.push_back({placed_.back().get(), placement, object});
    id_ranges_.push_back({next_id_, std::uint32_t(placed_.size() - 1), true});
    next_id_ += count;
}

SceneObject RenderScene::object(std::uint32_t id) const {
    const auto after =
        std::upper_bound(id_ranges_.begin(), id_ranges_.end(), id,
                         [](std::uint32_t wanted, const IdRange& range) { return wanted < range.first_id; });
    const IdRange& range = *std::prev(after);
    return range.placed ? placed_[range.index]->copy(id - range.first_id) : objects_[range.index];
}

void RenderScene::add_light(std::unique_ptr<Light> light) { lights_.push_back(std::move(light)); }

RTCScene RenderScene::new_shape_scene(RTCGeometry geometry) {
    RTCScene child = rtcNewScene(embree_device());
    shape_scenes_.push_back(child);
    rtcAttachGeometry(child, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(child);
    return child;
}

void RenderScene::attach(RTCGeometry geometry, const TracedGeometry& traced, const std::string& name) {
    const unsigned id = rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    if (traced_.size() <= id) traced_.resize(id + 1);
    traced_[id] = traced;
    check_embree("adding object \"" + name + "\"");
}

namespace {

std::size_t object_record_bytes(const SceneObject& object) {
    return sizeof(SceneObject) + (object.name.capacity() > std::string().capacity() ? object.name.capacity() : 0) +
           object.part_materials.capacity() * sizeof(const Material*);
}

}  // namespace

void RenderScene::commit() {
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t bytes_before = embree_bytes_in_use();
    RTCDevice device = embree_device();
    const auto count_shape = [&](const Shape& shape) {
        build_statistics_.primitives_by_type[shape.type_name()] += shape.primitive_count();
        build_statistics_.shape_bytes += shape.memory_bytes();
    };
    // The arrays of placements, with the scenes of their shapes, traced after the objects in world space.
    struct Traced {
        PlacementArray* array;
        RTCScene shape_scene;
        std::uint32_t first_id;
    };
    std::vector<Traced> arrays;
    std::unordered_map<const Shape*, RTCScene> scene_of_placed_shape;
    std::size_t user_primitives = 0;  // of the user geometries in the scene itself, and their box
    Bounds3f user_bounds;
    for (const IdRange& range : id_ranges_) {
        if (range.placed) {
            PlacementArray& array = *placed_[range.index];
            Shape& shape = array.shape();
            auto [built, first_use] = scene_of_placed_shape.try_emplace(&shape, nullptr);
            if (first_use) {  // a placed shape is named after its definition, and stays in its own space
                count_shape(shape);
                RTCGeometry geometry = shape.create_geometry(device);
                check_embree("building the shape of \"" + shape.object_name() + "\"");
                built->second = new_shape_scene(geometry);
                ++build_statistics_.placed_shapes;
            }
            arrays.push_back({&array, built->second, range.first_id});
            build_statistics_.placements += array.size();
            continue;
        }
        SceneObject& object = objects_[range.index];
        Shape& shape = *object.shape;
        object.counter_slot = counters::geometry_type_slot(shape.type_name(), shape.counts_intersection_tests());
        build_statistics_.object_bytes += object_record_bytes(object);
        count_shape(shape);
        object.instanced = !shape.can_bake(object.to_world);
        if (!object.instanced) shape.bake(object.to_world);
        object.hit_shading = shape.hit_shading();
        object.triangles = shape.embree_triangles();
        shape.set_object_name(object.name);
        RTCGeometry geometry = shape.create_geometry(device);
        check_embree("building object \"" + object.name + "\"");
        if (!object.instanced) {
            if (shape.counts_intersection_tests()) {
                user_primitives += shape.primitive_count();
                const Bounds3f own = shape.bounds();
                if (!own.empty()) user_bounds.extend(own.lower), user_bounds.extend(own.upper);
            }
            attach(geometry, {&object, nullptr, range.first_id}, object.name);
            continue;
        }
        // Traced in its own space as a placement is, so that both give the same hits.
        const std::optional<PlacementRecord> record = placement_record(object.to_world, 0);
        if (!record)
            throw std::runtime_error("object \"" + object.name + "\": its transform is singular in single precision");
        single_placements_.push_back(std::make_unique<PlacementArray>(
            object.shape, std::vector{&std::as_const(object)}, std::vector{*record},
            PlacementNames{object.name, "", {}}));
        arrays.push_back({single_placements_.back().get(), new_shape_scene(geometry), range.first_id});
    }
    if (!arrays.empty()) {
        // The placements' own scene. Many placements are built by Embree's quicker builder, whose BVH costs a fifth
        // of the default one's per placement but is looser; a few by the default one, which traces them faster
        // (docs/decisions.md, "Instances: one shape, many placements"). One instance, with no transform, puts the
        // scene in the scene. Its geometries take ids after the scene's own, so that a hit's geomID says which it is.
        RTCScene placements = rtcNewScene(device);
        shape_scenes_.push_back(placements);
        std::size_t count = 0;
        for (const Traced& traced : arrays) count += traced.array->size();
        rtcSetSceneBuildQuality(placements, count >= kPlacementsBuiltCompactly ? RTC_BUILD_QUALITY_LOW
                                                                                : RTC_BUILD_QUALITY_MEDIUM);
        const auto instance_id = unsigned(traced_.size());
        traced_.emplace_back();  // the instance: hits on it are hits on its placements
        for (const Traced& traced : arrays) {
            traced_.push_back({nullptr, traced.array, traced.first_id});
            RTCGeometry geometry = traced.array->create_geometry(device, traced.shape_scene);
            rtcAttachGeometryByID(placements, geometry, unsigned(traced_.size() - 1));
            rtcReleaseGeometry(geometry);
            check_embree("adding the placements of \"" + traced.array->names().object + "\"");
            build_statistics_.instanced_objects += traced.array->size();
            build_statistics_.object_bytes += traced.array->memory_bytes();
        }
        if (count == 1) {
            RTCBounds own;
            rtcGetSceneBounds(arrays.front().shape_scene, &own);
            const Vec3d centre = 0.5 * (Vec3d(own.lower_x, own.lower_y, own.lower_z) + Vec3d(own.upper_x, own.upper_y, own.upper_z));
            placements_sentinel_.add_to(device, placements, Vec3f(arrays.front().array->to_world(0).point(centre)));
        }
        rtcCommitScene(placements);
        RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(instance, placements);
        rtcCommitGeometry(instance);
        rtcAttachGeometryByID(scene_, instance, instance_id);
        rtcReleaseGeometry(instance);
        check_embree("adding the placements");
    }
    for (SceneObject& variant : placement_variants_) {
        const Shape& shape = *variant.shape;
        variant.instanced = true;
        variant.hit_shading = shape.hit_shading();
        variant.triangles = shape.embree_triangles();
        variant.counter_slot = counters::geometry_type_slot(shape.type_name(), shape.counts_intersection_tests());
        build_statistics_.object_bytes += object_record_bytes(variant);
    }
    if (user_primitives == 1 && !user_bounds.empty())  // its id comes after every id the hits use
        scene_sentinel_.add_to(device, scene_, 0.5f * (user_bounds.lower + user_bounds.upper));
    rtcCommitScene(scene_);
    check_embree("building the scene BVH");
    build_lights();
    build_statistics_.objects = next_id_;
    build_statistics_.embree_bytes = embree_bytes_in_use() - bytes_before;
    build_statistics_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

namespace {

// Embree stores the hit's fields one by one: each is read alone (a volatile load is never merged with its
// neighbours), since a wider load would span several of those stores and wait until they are written (a failed
// store forwarding).
template <class Field>
Field alone(const Field& field) {
    return *static_cast<const volatile Field*>(&field);
}

// The fields of Embree's hit that hit completion reads, copied one by one (see alone).
RTCHit fields_of(const RTCHit& hit) {
    RTCHit copy;
    copy.Ng_x = alone(hit.Ng_x), copy.Ng_y = alone(hit.Ng_y), copy.Ng_z = alone(hit.Ng_z);
    copy.u = alone(hit.u), copy.v = alone(hit.v);
    copy.primID = alone(hit.primID), copy.geomID = alone(hit.geomID), copy.instID[0] = alone(hit.instID[0]);
    return copy;
}

// Four rows of four floats turned into their four columns.
void transpose(Float4& a, Float4& b, Float4& c, Float4& d) {
    const Float4 ab_low = __builtin_shufflevector(a, b, 0, 4, 1, 5), ab_high = __builtin_shufflevector(a, b, 2, 6, 3, 7);
    const Float4 cd_low = __builtin_shufflevector(c, d, 0, 4, 1, 5), cd_high = __builtin_shufflevector(c, d, 2, 6, 3, 7);
    a = __builtin_shufflevector(ab_low, cd_low, 0, 1, 4, 5);
    b = __builtin_shufflevector(ab_low, cd_low, 2, 3, 6, 7);
    c = __builtin_shufflevector(ab_high, cd_high, 0, 1, 4, 5);
    d = __builtin_shufflevector(ab_high, cd_high, 2, 3, 6, 7);
}

// Writes the rays of the `live` lanes that Embree can trace (is_traceable) into `query` and marks them valid;
// counts the others and returns their lanes. The eight rays' first eight floats (origin, direction, t_near, t_far)
// are loaded as rows and transposed into Embree's columns, and the test runs on the columns, without a branch per
// lane: lane by lane it took about 65 instructions a ray. Every lane is written (Embree reads only the valid ones).
unsigned set_packet(std::span<const Ray> rays, unsigned live, RTCRay8& query, std::array<std::int32_t, 8>& valid) {
    static_assert(kLanes == 8 && offsetof(Ray, direction) == 12 && offsetof(Ray, t_near) == 24 &&
                  offsetof(Ray, t_far) == 28);
    if (rays.size() < std::size_t(kLanes)) [[unlikely]] {  // read from a copy of eight
        std::array<Ray, kLanes> padded;
        std::copy(rays.begin(), rays.end(), padded.begin());
        return set_packet(padded, live, query, valid);
    }
    // columns[c] holds float c of the rays 0-3, columns[8 + c] of the rays 4-7.
    std::array<Float4, 16> columns;
    for (std::size_t half = 0; half < 2; ++half)
        for (std::size_t row = 0; row < 4; ++row) {
            const auto* first = reinterpret_cast<const char*>(&rays[4 * half + row]);
            std::memcpy(&columns[8 * half + row], first, sizeof(Float4));
            std::memcpy(&columns[8 * half + 4 + row], first + sizeof(Float4), sizeof(Float4));
        }
    for (std::size_t quarter = 0; quarter < 4; ++quarter) {
        Float4* rows = &columns[4 * quarter];
        transpose(rows[0], rows[1], rows[2], rows[3]);
    }
    const auto column = [&](std::size_t c) { return __builtin_shufflevector(columns[c], columns[8 + c], 0, 1, 2, 3, 4, 5, 6, 7); };
    const FloatLanes origin_x = column(0), origin_y = column(1), origin_z = column(2), direction_x = column(3);
    const FloatLanes direction_y = column(4), direction_z = column(5), t_near = column(6), t_far = column(7);
    const IntLanes live_lanes = lanes_of_bits(live);
    const IntLanes ok = traceable(origin_x, origin_y, origin_z, direction_x, direction_y, direction_z, t_near, t_far);
    store_lanes(valid.data(), live_lanes & ok);
    store_lanes(query.org_x, origin_x);
    store_lanes(query.org_y, origin_y);
    store_lanes(query.org_z, origin_z);
    store_lanes(query.dir_x, direction_x);
    store_lanes(query.dir_y, direction_y);
    store_lanes(query.dir_z, direction_z);
    store_lanes(query.tnear, t_near);
    store_lanes(query.tfar, t_far);
    // Every geometry is seen (mask all ones: Debian's Embree has ray masks on); time, id and flags 0.
    store_lanes(reinterpret_cast<std::int32_t*>(query.mask), splat(-1));
    store_lanes(query.time, splat(0.0f));
    store_lanes(reinterpret_cast<std::int32_t*>(query.id), splat(0));
    store_lanes(reinterpret_cast<std::int32_t*>(query.flags), splat(0));
    const unsigned untraceable = lane_bits(live_lanes & ~ok);
    if (untraceable) [[unlikely]] RenderScene::count_untraceable_rays(std::uint64_t(std::popcount(untraceable)));
    return untraceable;
}

}  // namespace

std::optional<SurfaceHit> RenderScene::intersect(const Ray& ray, RayKind kind) const {
    counters::count_ray(kind);
    // Every return returns this one object, so that it is built where the caller receives it (a hit built apart
    // was copied there: 176 bytes per hit).
    std::optional<SurfaceHit> found;
    QueryContext context(scratch_pool_);
    RTCRayHit query;  // set_embree_ray writes the whole ray; Embree reads only geomID and instID of the hit
    // The path tracer stores a ray's fields one or two at a time just before asking: each is read alone (above).
    const Ray fields{{alone(ray.origin.x), alone(ray.origin.y), alone(ray.origin.z)},
                     {alone(ray.direction.x), alone(ray.direction.y), alone(ray.direction.z)},
                     alone(ray.t_near), alone(ray.t_far)};
    if (!is_traceable(fields)) [[unlikely]] {
        count_untraceable_rays(1);
        return found;
    }
    set_embree_ray(query.ray, fields);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context.embree, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return found;
    complete_hit(ray, query.hit, query.ray.tfar, found);
    return found;
}

void RenderScene::intersect(std::span<const Ray> rays, unsigned live, RayKind kind,
                            std::span<std::optional<SurfaceHit>> found) const {
    if (std::has_single_bit(live)) {  // a packet of one costs more than the ray alone
        for (std::size_t lane = 0; lane < rays.size(); ++lane) found[lane].reset();
        const auto lane = std::size_t(std::countr_zero(live));
        found[lane] = intersect(rays[lane], kind);
        return;
    }
    counters::count_rays(kind, std::uint64_t(std::popcount(live)));
    QueryContext context(scratch_pool_);
    // A pixel's camera rays are alike, and Embree traverses such a packet as one; later rays have scattered.
    if (kind == RayKind::Camera) context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    RTCRayHit8 query;  // Embree reads only the valid lanes
    alignas(32) std::array<std::int32_t, 8> valid;
    set_packet(rays, live, query.ray, valid);  // an untraceable ray misses
    store_lanes(reinterpret_cast<std::int32_t*>(query.hit.geomID), splat(std::int32_t(RTC_INVALID_GEOMETRY_ID)));
    store_lanes(reinterpret_cast<std::int32_t*>(query.hit.instID[0]), splat(std::int32_t(RTC_INVALID_GEOMETRY_ID)));
    rtcIntersect8(valid.data(), scene_, &context.embree, &query);
    const unsigned hits = lane_bits(load_lanes(valid.data()) &
                                    (load_lanes(reinterpret_cast<const std::int32_t*>(query.hit.geomID)) !=
                                     std::int32_t(RTC_INVALID_GEOMETRY_ID)));
    for (std::size_t lane = 0; lane < rays.size(); ++lane) {
        if (!(hits >> lane & 1u)) {
            found[lane].reset();
            continue;
        }
        RTCHit hit;
        hit.Ng_x = query.hit.Ng_x[lane];
        hit.Ng_y = query.hit.Ng_y[lane];
        hit.Ng_z = query.hit.Ng_z[lane];
        hit.u = query.hit.u[lane];
        hit.v = query.hit.v[lane];
        hit.primID = query.hit.primID[lane];
        hit.geomID = query.hit.geomID[lane];
        hit.instID[0] = query.hit.instID[0][lane];
        complete_hit(rays[lane], hit, query.ray.tfar[lane], found[lane]);
    }
}

unsigned RenderScene::occluded(std::span<const Ray> rays, unsigned live) const {
    if (std::has_single_bit(live)) {  // as for intersect
        const int lane = std::countr_zero(live);
        return occluded(rays[std::size_t(lane)]) ? live : 0u;
    }
    counters::count_rays(RayKind::Shadow, std::uint64_t(std::popcount(live)));
    QueryContext context(scratch_pool_);  // two passes, as occluded(const Ray&) takes them
    context.occlusion_pass = OcclusionPass::AwayFromStarts;
    RTCRay8 query;  // Embree reads only the valid lanes
    alignas(32) std::array<std::int32_t, 8> valid;
    const unsigned untraceable = set_packet(rays, live, query, valid);  // no light arrives along an untraceable ray
    context.rays = &query, context.ray_count = 8;
    rtcOccluded8(valid.data(), scene_, &context.embree, &query);
    const auto blocked = [&] {
        return lane_bits(load_lanes(valid.data()) & (load_lanes(query.tfar) == -std::numeric_limits<float>::infinity()));
    };
    unsigned found = blocked();
    if (context.put_off.any()) {
        const IntLanes open = load_lanes(valid.data()) & ~lanes_of_bits(found);
        if (lane_bits(open) && context.put_off.all_kept()) {
            found |= context.put_off.ask(lane_bits(open));
        } else if (lane_bits(open)) {
            store_lanes(valid.data(), open);  // the rays nothing blocked, as they were
            context.occlusion_pass = OcclusionPass::AtStarts;
            rtcOccluded8(valid.data(), scene_, &context.embree, &query);
            found |= blocked();
        }
    }
    return untraceable | found;
}

void RenderScene::complete_hit(const Ray& ray, const RTCHit& found_hit, float t,
                               std::optional<SurfaceHit>& found) const {
    // A placement array's hit names the placement in instID[0] (PlacementArray::intersect).
    const TracedGeometry& traced = traced_[found_hit.geomID];
    const std::uint32_t placement = traced.placements ? found_hit.instID[0] : 0;
    const SceneObject& object = traced.placements ? traced.placements->variant_of(placement) : *traced.object;
    const std::uint32_t object_index = traced.id + placement;
    counters::count_closest_hit(object.counter_slot);
    const PlacementRecord* record = traced.placements ? &traced.placements->record(placement) : nullptr;
    std::optional<Transform> computed;  // a placed copy's, computed from its record
    const Transform& to_world = record ? computed.emplace(to_world_of_record(*record)) : object.to_world;

    RTCHit solved;  // a triangle hit's numbers solved again, in the triangles' own space
    if (!object.triangles.empty()) {
        solved = fields_of(found_hit);
        if (object.instanced)
            resolve_triangle_hit(object.triangles, Vec3f(to_world.inverse_point(Vec3d(ray.origin))),
                                 Vec3f(to_world.inverse_vector(Vec3d(ray.direction))), solved, t);
        else
            resolve_triangle_hit(object.triangles, ray.origin, ray.direction, solved, t);
    }
    const RTCHit& embree_hit = object.triangles.empty() ? found_hit : solved;

    // The normal is read a float at a time, and the result is built once from registers rather than in pieces on
    // the stack.
    const Vec3f embree_ng =
        safe_normalize(Vec3f(alone(embree_hit.Ng_x), alone(embree_hit.Ng_y), alone(embree_hit.Ng_z)), {0, 0, 1});
    const auto shape_shading = [&] {
        // The hit in the shape's own space (object space when instanced), for shapes that compute normals there.
        const Vec3d world_point = Vec3d(ray.origin) + Vec3d(ray.direction) * double(t);
        const Vec3d local_point = object.instanced ? to_world.inverse_point(world_point) : world_point;
        return object.shape->shading(embree_hit, embree_ng, local_point);
    };
    const LocalShading local =
        object.hit_shading == HitShading::Computed
            ? shape_shading()
            : shading_of_embree_hit(embree_hit, embree_ng, object.hit_shading == HitShading::EmbreeHitSwappedUv);
    Vec3f geometric_normal = local.geometric_normal, shading_normal = local.normal;
    Vec3f dpdu = local.dpdu, dpdv = local.dpdv;
    if (object.instanced) {  // the hit's Ng is in the shape's space
        geometric_normal = safe_normalize(to_world.normal(local.geometric_normal), local.geometric_normal);
        shading_normal = safe_normalize(to_world.normal(local.normal), geometric_normal);
        dpdu = to_world.vector(dpdu);
        dpdv = to_world.vector(dpdv);
    }
    if (dot(shading_normal, geometric_normal) < 0) shading_normal = -shading_normal;
    const Vec3f position = ray.at(t);
    const float position_error = kPositionErrorScale * (max_component(abs(position)) + t * length(ray.direction));
    SurfaceHit& hit = found.emplace();  // field by field: a hit built apart is copied in
    hit.t = t;
    hit.position = position;
    hit.geometric_normal = geometric_normal;
    hit.shading_normal = shading_normal;
    hit.uv = local.uv;
    hit.object_index = object_index;
    hit.primitive_id = embree_hit.primID;
    hit.material = local.blend.count > 0 && object.blended_material ? object.blended_material
                                                                    : object.material_of_part(local.part);
    hit.position_error = position_error;
    hit.dpdu = dpdu;
    hit.dpdv = dpdv;
    hit.footprint = ray.cone_width + ray.cone_spread * t * length(ray.direction);
    hit.object = &object;
    hit.placement = record;
    hit.blend = local.blend;
    if (hit.material) hit.material->perturb_normal(hit);
}

void RenderScene::count_untraceable_rays(std::uint64_t count) {
    static const int slot = counters::named_counter_slot("rays.untraceable");
    counters::add_to_named<1>({slot}, {count});
}

void RenderScene::build_lights() {
    // Emission found by rays: every emissive material, also per-part ones and those of unsampled emitters.
    const auto note_emission = [&](const SceneObject& object) {
        if (object.material && object.material->is_emissive()) emission_can_be_hit_ = true;
        for (const Material* part : object.part_materials)
            if (part && part->is_emissive()) emission_can_be_hit_ = true;
        return object.material && object.material->is_emissive();
    };
    // An object's light, in world space or placed as its hits are (to_world_of_record), in the order of the ids.
    // Each owner learns the light's probability once every light's power is known (below).
    std::vector<std::pair<SceneObject*, std::size_t>> area_light_owners;  // with the light's index in lights_
    const auto add_area_light = [&](SceneObject& object, std::optional<Transform> placed) {
        lights_.push_back(std::make_unique<AreaLight>(*object.shape, *object.material, std::move(placed)));
        object.area_light.light = lights_.back().get();
        area_light_owners.emplace_back(&object, lights_.size() - 1);
        ++build_statistics_.area_lights;
    };
    auto emissive_placement = emissive_placements_.begin();
    for (const IdRange& range : id_ranges_) {
        if (range.placed) {
            const PlacementArray& array = *placed_[range.index];
            for (; emissive_placement != emissive_placements_.end() && emissive_placement->array == &array;
                 ++emissive_placement)
                add_area_light(*emissive_placement->object, array.to_world(emissive_placement->placement));
            for (std::uint32_t placement = 0; placement < array.size(); ++placement)
                if (note_emission(array.variant_of(placement)) && !array.variant_of(placement).area_light.light)
                    ++build_statistics_.unsampled_emitters;
            continue;
        }
        SceneObject& object = objects_[range.index];
        if (!note_emission(object)) continue;
        if (!object.shape->supports_surface_sampling()) {
            ++build_statistics_.unsampled_emitters;
            continue;
        }
        add_area_light(object, object.instanced ? std::optional(to_world_of_record(*placement_record(object.to_world, 0)))
                                                : std::nullopt);
    }
    const Bounds3f scene_bounds = bounds();
    std::vector<float> powers;
    for (const auto& light : lights_) {
        light->preprocess(scene_bounds);
        all_lights_.push_back(light.get());
        powers.push_back(std::max(0.0f, light->power()));
    }
    light_sampling_is_deterministic_ = all_lights_.size() <= 1 && (all_lights_.empty() || all_lights_[0]->is_delta());
    if (powers.empty()) return;
    light_distribution_ = std::make_unique<Distribution1D>(powers);
    for (std::size_t i = 0; i < all_lights_.size(); ++i)
        if (all_lights_[i]->is_infinite()) {
            infinite_lights_.push_back({all_lights_[i], light_distribution_->probability(i)});
            emission_can_be_hit_ = true;
        }
    for (const auto& [object, index] : area_light_owners)
        object->area_light.probability = light_distribution_->probability(index);
}

LightChoice RenderScene::choose_light(float u) const {
    if (!light_distribution_) return {};
    const Distribution1D::DiscreteSample pick = light_distribution_->sample_discrete(u);
    return {all_lights_[pick.index], pick.probability};
}

Bounds3f RenderScene::bounds() const {
    bool unbounded = false;
    for (const SceneObject& object : objects_) unbounded = unbounded || object.shape->is_unbounded();
    for (const auto& array : placed_) unbounded = unbounded || array->shape().is_unbounded();
    Bounds3f result;
    if (!unbounded) {
        RTCBounds b;
        rtcGetSceneBounds(scene_, &b);
        result.lower = {b.lower_x, b.lower_y, b.lower_z};
        result.upper = {b.upper_x, b.upper_y, b.upper_z};
        return result;
    }
    // Embree's box then reaches the world's edge: the extent is that of the other objects' own bounds, or a metre
    // around the origin when there are none (lights at infinity need some extent to weigh their power by).
    const auto extend = [&](const Shape& shape, const Transform* to_world) {
        const Bounds3f own = shape.bounds();
        if (shape.is_unbounded() || own.empty()) return;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3d p = box_corner(Vec3d(own.lower), Vec3d(own.upper), corner);
            result.extend(Vec3f(to_world ? to_world->point(p) : p));
        }
    };
    // Objects traced in their shape's space are placed as their hits are (to_world_of_record), so that an object
    // and the same placed copy give the same extent.
    for (const SceneObject& object : objects_)
        if (!object.instanced) extend(*object.shape, nullptr);
    for (const auto* arrays : {&placed_, &single_placements_})
        for (const auto& array : *arrays)
            for (std::uint32_t placement = 0; placement < array->size(); ++placement) {
                const Transform to_world = array->to_world(placement);
                extend(array->shape(), &to_world);
            }
    if (result.empty()) {
        result.extend({-1, -1, -1});
        result.extend({1, 1, 1});
    }
    return result;
}

}  // namespace isotrace
