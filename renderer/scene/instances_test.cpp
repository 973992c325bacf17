#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <malloc.h>
#include <unistd.h>
#include <set>
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "renderer/plugin/shape.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/scene_files.h"
#include "tests/support/scoped_environment_variable.h"

namespace isotrace {
namespace {

std::string scene_with(const std::string& top_level) {
    return R"({"isotrace": 1,
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 20], "target": [0, 0, 0]}},
  "materials": {"grey": {"type": "diffuse"}, "red": {"type": "diffuse", "reflectance": [0.8, 0.1, 0.1]},
                "blue": {"type": "diffuse", "reflectance": [0.1, 0.1, 0.8]}},
)" + top_level + "}\n";
}

// Transforms that no shape here can bake (a non-uniform scale), so that objects written out separately are placed
// in their shapes' space as the placements are.
const std::vector<std::string> kTransforms = {
    R"({"translate": [-4, 0, 0], "scale": [1, 0.5, 1.5]})",
    R"([{"scale": [0.7, 1.3, 1]}, {"rotate": {"axis": [1, 2, 3], "angle": 40}}, {"translate": [0, 3, -1]}])",
    R"({"translate": [3.5, -2, 1], "rotate": [10, 20, 30], "scale": [1.2, 0.9, 0.6]})",
    R"({"translate": [0.5, 0.2, 2], "scale": [0.4, 0.8, 0.5]})"};
const std::vector<std::string> kMaterials = {"", "red", "", "blue"};  // "": the definition's own

// `shape` placed at every kTransforms entry as instances of one definition.
std::string instanced_scene(const std::string& shape) {
    std::string placements;
    for (std::size_t i = 0; i < kTransforms.size(); ++i)
        placements += std::string(i ? ", " : "") + R"({"transform": )" + kTransforms[i] +
                      (kMaterials[i].empty() ? "" : R"(, "material": ")" + kMaterials[i] + "\"") + "}";
    return scene_with(R"("definitions": {"thing": {"material": "grey", "shape": )" + shape + R"(}},
  "objects": [{"name": "things", "instance": "thing", "placements": [)" + placements + "]}]\n");
}

// The same objects written out one by one, each with its own shape.
std::string separate_scene(const std::string& shape) {
    std::string objects;
    for (std::size_t i = 0; i < kTransforms.size(); ++i)
        objects += std::string(i ? ",\n" : "") + R"({"name": "things[)" + std::to_string(i) + R"(]", "material": ")" +
                   (kMaterials[i].empty() ? "grey" : kMaterials[i]) + R"(", "transform": )" + kTransforms[i] +
                   R"(, "shape": )" + shape + "}";
    return scene_with(R"("objects": [)" + objects + "]\n");
}

const std::string kSpheres = R"({"type": "sphere", "spheres": [{"center": [0, 0, 0], "radius": 1}, {"center": [0.8, 0.6, 0], "radius": 0.5}]})";
const std::string kBlobs = R"({"type": "blobs", "field": "kim", "threshold": 0.5, "elements": [
    {"center": [0, 0, 0], "half_size": [0.8, 0.3, 0.3], "radius": 0.5, "weight": 1},
    {"center": [0.9, 0.4, 0], "half_size": 0.2, "radius": 0.4, "weight": 1, "rotate": [0, 0, 30]},
    {"center": [-0.9, -0.3, 0.2], "radius": 0.6, "weight": 0.8}]})";
const std::string kMesh = R"({"type": "mesh", "positions": [[-1, -1, -1], [1, -1, -1], [0, 1, -1], [0, 0, 1]],
    "triangles": [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]]})";

// A shape that never lets its transform be baked: meshes bake every transform, so written out separately they are
// traced in world space; wrapped in this, they are traced in their own space, as placements are.
class RefusesBaking : public Shape {
public:
    explicit RefusesBaking(std::unique_ptr<Shape> inner) : inner_(std::move(inner)) {}
    std::string type_name() const override { return inner_->type_name(); }
    std::size_t primitive_count() const override { return inner_->primitive_count(); }
    std::size_t memory_bytes() const override { return inner_->memory_bytes(); }
    Bounds3f bounds() const override { return inner_->bounds(); }
    bool can_bake(const Transform&) const override { return false; }
    void bake(const Transform&) override {}
    RTCGeometry create_geometry(RTCDevice device) override { return inner_->create_geometry(device); }
    LocalShading shading(const RTCHit& hit, const Vec3f& ng, const Vec3d& point) const override {
        return inner_->shading(hit, ng, point);
    }
    HitShading hit_shading() const override { return inner_->hit_shading(); }
    TriangleView embree_triangles() const override { return inner_->embree_triangles(); }
    bool has_uv() const override { return inner_->has_uv(); }

private:
    std::unique_ptr<Shape> inner_;
};

struct TracedHit {
    bool hit = false;
    float t = 0;
    Vec3f position, geometric_normal, shading_normal;
    std::string object, material;
};

// The nearest hits of a fan of rays from the camera's eye over the scene, with object and material names.
std::vector<TracedHit> trace_fan(const LoadedScene& loaded) {
    const RenderScene& scene = *loaded.scene;
    std::vector<TracedHit> hits;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Vec3f direction = normalize(Vec3f(float(x - 32) / 150.0f, float(y - 32) / 150.0f, -1.0f));
            Ray ray{{0, 0, 20}, direction, 0, 1e30f};
            TracedHit traced;
            if (const auto hit = scene.intersect(ray, RayKind::Camera)) {
                traced = {true, hit->t, hit->position, hit->geometric_normal, hit->shading_normal,
                          scene.object(hit->object_index).name, ""};
                for (const std::string& name : scene.material_names())
                    if (scene.find_material(name) == hit->material) traced.material = name;
            }
            hits.push_back(traced);
        }
    return hits;
}

bool same_bits(const Vec3f& a, const Vec3f& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

class Instances : public ::testing::Test {
protected:
    ScopedEnvironmentVariable no_ocio_{"OCIO", std::nullopt};
    testing::TemporaryDirectory dir_{"instances"};

    std::unique_ptr<LoadedScene> load(const std::string& text, const SceneOverrides& overrides = {}) {
        return load_scene(dir_.write("scene.json", text).string(), overrides);
    }

    void expect_same_hits(const std::string& shape, const SceneOverrides& overrides = {}) {
        const auto instanced = load(instanced_scene(shape), overrides);
        const auto separate = load(separate_scene(shape), overrides);
        EXPECT_EQ(instanced->scene->build_statistics().placements, kTransforms.size());
        EXPECT_EQ(instanced->scene->build_statistics().placed_shapes, 1u);
        EXPECT_EQ(separate->scene->build_statistics().instanced_objects, kTransforms.size());
        const std::vector<TracedHit> a = trace_fan(*instanced), b = trace_fan(*separate);
        std::size_t hit_count = 0, differing = 0;
        std::set<std::string> objects_hit;
        for (std::size_t i = 0; i < a.size(); ++i) {
            hit_count += a[i].hit;
            if (a[i].hit) objects_hit.insert(a[i].object);
            const bool same = a[i].hit == b[i].hit && std::memcmp(&a[i].t, &b[i].t, sizeof(float)) == 0 &&
                              same_bits(a[i].position, b[i].position) &&
                              same_bits(a[i].geometric_normal, b[i].geometric_normal) &&
                              same_bits(a[i].shading_normal, b[i].shading_normal) && a[i].object == b[i].object &&
                              a[i].material == b[i].material;
            differing += !same;
        }
        EXPECT_EQ(differing, 0u) << "of " << a.size() << " rays";
        EXPECT_GT(hit_count, a.size() / 20) << "the rays must see the shapes";
        EXPECT_EQ(objects_hit.size(), kTransforms.size()) << "every placement is seen";
    }
};

TEST_F(Instances, SpheresGiveTheSameHitsAsSeparateObjects) { expect_same_hits(kSpheres); }

TEST_F(Instances, BlobGroupsGiveTheSameHitsAsSeparateObjects) { expect_same_hits(kBlobs); }

TEST_F(Instances, MeshesGiveTheSameHitsAsSeparateObjectsInInstances) {
    SceneOverrides overrides;
    overrides.replace_shape = [](std::unique_ptr<Shape> shape) -> std::unique_ptr<Shape> {
        return std::make_unique<RefusesBaking>(std::move(shape));
    };
    expect_same_hits(kMesh, overrides);
}

TEST_F(Instances, ShapesAreBuiltAndCountedOnce) {
    const auto loaded = load(instanced_scene(kBlobs));
    const BuildStatistics& build = loaded->scene->build_statistics();
    const auto one = load(scene_with(R"("objects": [{"material": "grey", "shape": )" + kBlobs + "}]\n"));
    EXPECT_EQ(build.primitives_by_type.at("blobs"), one->scene->build_statistics().primitives_by_type.at("blobs"));
    EXPECT_EQ(build.shape_bytes, one->scene->build_statistics().shape_bytes);
    const RenderScene& scene = *loaded->scene;
    EXPECT_TRUE(scene.objects().empty()) << "placements are not objects of their own";
    ASSERT_EQ(scene.object_count(), kTransforms.size());
    for (std::uint32_t id = 0; id < scene.object_count(); ++id) {
        EXPECT_EQ(scene.object(id).shape, scene.object(0).shape) << "one shape for every placement";
        EXPECT_TRUE(scene.object(id).instanced);
    }
    EXPECT_EQ(scene.object(0).shape->object_name(), "thing") << "a shared shape keeps statistics under its definition";
    EXPECT_EQ(scene.object(2).name, "things[2]");
}

// A hit names its placement: its id and its own transform (which object-space textures read), the materials of the
// copy it shows, and as an object of its own, its name and transform.
TEST_F(Instances, AHitCarriesItsPlacement) {
    const auto loaded = load(scene_with(R"("objects": [{"name": "floor", "material": "grey", "shape": {"type": "mesh",
    "positions": [[-9, -9, -5], [9, -9, -5], [0, 9, -5]], "triangles": [[0, 1, 2]]}},
  {"name": "balls", "instance": "ball", "placements": [{"transform": {"translate": [-3, 0, 0], "scale": [1, 2, 1]}},
    {"name": "blue one", "material": "blue", "transform": {"translate": [3, 0, 0]}}]}],
  "definitions": {"ball": {"material": "red", "shape": {"type": "sphere", "radius": 1}}}
)"));
    const RenderScene& scene = *loaded->scene;
    ASSERT_EQ(scene.object_count(), 3u);
    EXPECT_EQ(scene.objects().size(), 1u);
    const auto left = scene.intersect(Ray{{-3, 1.5f, 10}, {0, 0, -1}, 0, 1e30f}, RayKind::Camera);
    const auto right = scene.intersect(Ray{{3, 0, 10}, {0, 0, -1}, 0, 1e30f}, RayKind::Camera);
    const auto floor = scene.intersect(Ray{{0, 0, 10}, {0, 0, -1}, 0, 1e30f}, RayKind::Camera);
    ASSERT_TRUE(left && right && floor);
    EXPECT_EQ(floor->object_index, 0u);
    EXPECT_EQ(left->object_index, 1u);
    EXPECT_EQ(right->object_index, 2u);
    EXPECT_EQ(scene.object(1).name, "balls[0]");
    EXPECT_EQ(scene.object(2).name, "blue one");
    EXPECT_EQ(left->material, scene.find_material("red"));
    EXPECT_EQ(right->material, scene.find_material("blue"));
    std::optional<Transform> left_computed, right_computed;
    EXPECT_EQ(left->to_world(left_computed).matrix(), scene.object(1).to_world.matrix());
    EXPECT_NEAR(left->to_world(left_computed).matrix()[1][1], 2.0, 1e-7);
    EXPECT_NEAR(right->to_world(right_computed).matrix()[0][3], 3.0, 1e-7);
    EXPECT_NEAR(left->t, 10.0f - std::sqrt(1.0f - 0.75f * 0.75f), 1e-5f);  // the ellipsoid's surface at y = 1.5
}

// A metacube creature: a body, a head, four legs and a tail.
const std::string kCreature = R"({"type": "blobs", "field": "kim", "threshold": 0.5, "elements": [
    {"center": [0, 1.5, 0], "half_size": [1, 0.3, 0.35], "radius": 0.55, "weight": 1},
    {"center": [1.4, 2.2, 0], "half_size": [0.3, 0.28, 0.28], "radius": 0.5, "weight": 1},
    {"center": [0.8, 0.6, 0.3], "half_size": [0.1, 0.5, 0.1], "radius": 0.3, "weight": 1},
    {"center": [0.8, 0.6, -0.3], "half_size": [0.1, 0.5, 0.1], "radius": 0.3, "weight": 1},
    {"center": [-0.8, 0.6, 0.3], "half_size": [0.1, 0.5, 0.1], "radius": 0.3, "weight": 1},
    {"center": [-0.8, 0.6, -0.3], "half_size": [0.1, 0.5, 0.1], "radius": 0.3, "weight": 1},
    {"center": [-1.3, 2.0, 0], "half_size": [0.08, 0.35, 0.08], "radius": 0.25, "weight": 1, "rotate": [0, 0, 30]}]})";

std::uint64_t scene_bytes(const BuildStatistics& build) {
    return std::uint64_t(std::max<std::int64_t>(build.embree_bytes, 0)) + build.shape_bytes + build.object_bytes;
}

// What the process holds: the heap in use (malloc's own count) and the resident pages (Embree maps its large blocks
// itself, past malloc), each after returning the heap's free pages. Not under AddressSanitizer, whose allocator
// keeps freed blocks in quarantine and leaves malloc's count empty.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kProcessBytesTell = false;
#else
constexpr bool kProcessBytesTell = true;
#endif
struct ProcessBytes {
    std::int64_t heap = 0, resident = 0;
    static ProcessBytes now() {
        malloc_trim(0);
        const struct mallinfo2 info = mallinfo2();
        long pages = 0, resident_pages = 0;
        if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
            if (std::fscanf(statm, "%ld %ld", &pages, &resident_pages) != 2) resident_pages = 0;
            std::fclose(statm);
        }
        return {std::int64_t(info.uordblks + info.hblkhd), std::int64_t(resident_pages) * sysconf(_SC_PAGESIZE)};
    }
};

// 10^4 and 10^5 placements cost less than two copies of the creature and 100 bytes each, counted by what the scene
// keeps (Embree's memory, the shape, the objects and the placements' records) and by what the process holds while
// the scene is loaded: one copy of the shape and its BVH, and per placement a record and its share of the BVH over
// the placements — not a copy of the shape or of its BVH, nor an object or an Embree instance of its own.
TEST_F(Instances, PlacementsCostOneCopyAndAHundredBytesEach) {
    const auto one = load(scene_with(R"("objects": [{"material": "grey", "shape": )" + kCreature + "}]\n"));
    const std::uint64_t copy = scene_bytes(one->scene->build_statistics());
    for (const std::size_t side : {100, 317}) {
        const std::size_t count = side * side;
        const ProcessBytes before = ProcessBytes::now();
        auto many = load(scene_with(R"("definitions": {"creature": {"material": "grey", "shape": )" + kCreature +
                                    R"(}}, "objects": [{"instance": "creature", "grid": {"counts": [)" +
                                    std::to_string(side) + ", 1, " + std::to_string(side) +
                                    R"(], "spacing": [4, 0, 4], "rotate": {"angle": [0, 360]}, "seed": 3}}]
)"));
        const ProcessBytes after = ProcessBytes::now();
        const BuildStatistics& build = many->scene->build_statistics();
        ASSERT_EQ(build.placements, count);
        const std::uint64_t all = scene_bytes(build);
        const double allowed = 2.0 * double(copy) + 100.0 * double(count);
        std::printf("one copy %llu B (Embree %lld, shape %zu, object %zu); %zu placements %llu B (Embree %lld, shape "
                    "%zu, objects %zu): %.1f B per placement; the process: heap %.1f B, resident %.1f B per placement\n",
                    (unsigned long long)copy, (long long)one->scene->build_statistics().embree_bytes,
                    one->scene->build_statistics().shape_bytes, one->scene->build_statistics().object_bytes, count,
                    (unsigned long long)all, (long long)build.embree_bytes, build.shape_bytes, build.object_bytes,
                    double(all - copy) / double(count), double(after.heap - before.heap) / double(count),
                    double(after.resident - before.resident) / double(count));
        EXPECT_EQ(build.shape_bytes, one->scene->build_statistics().shape_bytes);
        EXPECT_LT(double(all), allowed);
        if (!kProcessBytesTell) continue;
        EXPECT_LT(double(after.heap - before.heap), allowed);
        // The resident pages also move by what the allocators keep around (a few hundred kilobytes): only many
        // placements make that small beside them.
        if (count > 100000) { EXPECT_LT(double(after.resident - before.resident), allowed); }
    }
}

// A group: its members keep their own materials and transforms; an override paints the whole copy.
const std::string kGroupScene = scene_with(R"("definitions": {
    "ball": {"material": "blue", "shape": {"type": "sphere", "radius": 1}},
    "pair": {"objects": [
      {"name": "left", "material": "grey", "shape": {"type": "sphere", "radius": 1}, "transform": {"translate": [-1.5, 0, 0]}},
      {"name": "right", "instance": "ball", "transform": {"translate": [1.5, 0, 0]}}]}},
  "objects": [{"name": "pairs", "instance": "pair", "placements": [
    {"transform": {"translate": [0, 2, 0]}}, {"transform": {"translate": [0, -2, 0]}, "material": "red"}]}]
)");

TEST_F(Instances, GroupsKeepTheirMaterialsUnlessOverridden) {
    const auto loaded = load(kGroupScene);
    const RenderScene& scene = *loaded->scene;
    ASSERT_EQ(scene.object_count(), 4u);
    // Numbered part by part: each part's copies are one array.
    EXPECT_EQ(scene.object(0).name, "pairs[0]/left");
    EXPECT_EQ(scene.object(1).name, "pairs[1]/left");
    EXPECT_EQ(scene.object(2).name, "pairs[0]/right");
    EXPECT_EQ(scene.object(3).name, "pairs[1]/right");
    EXPECT_EQ(scene.object(0).material, scene.find_material("grey"));
    EXPECT_EQ(scene.object(1).material, scene.find_material("red"));
    EXPECT_EQ(scene.object(2).material, scene.find_material("blue"));
    EXPECT_EQ(scene.object(3).material, scene.find_material("red"));
    EXPECT_EQ(scene.build_statistics().placed_shapes, 2u);
    // The group's transform and the placement's multiply: the right ball of the lower pair is centred at (1.5, -2, 0).
    const auto hit = scene.intersect(Ray{{1.5f, -2, 10}, {0, 0, -1}, 0, 1e30f}, RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_EQ(scene.object(hit->object_index).name, "pairs[1]/right");
    EXPECT_NEAR(hit->t, 9.0f, 1e-5f);
    EXPECT_EQ(hit->material, scene.find_material("red"));
}

TEST_F(Instances, AnOverrideReplacesThePartMaterialsOfAComposite) {
    const std::string blobs = R"({"type": "blobs", "elements": [
        {"center": [-0.4, 0, 0], "radius": 1, "material": "red"}, {"center": [0.4, 0, 0], "radius": 1}]})";
    const auto loaded = load(scene_with(R"("definitions": {"b": {"material": "grey", "shape": )" + blobs + R"(}},
  "objects": [{"name": "own", "instance": "b", "transform": {"translate": [-3, 0, 0]}},
              {"name": "painted", "instance": "b", "material": "blue", "transform": {"translate": [3, 0, 0]}}]
)"));
    const RenderScene& scene = *loaded->scene;
    const auto own = scene.intersect(Ray{{-3.4f, 0, 10}, {0, 0, -1}, 0, 1e30f}, RayKind::Camera);
    const auto painted = scene.intersect(Ray{{2.6f, 0, 10}, {0, 0, -1}, 0, 1e30f}, RayKind::Camera);
    ASSERT_TRUE(own && painted);
    EXPECT_NE(own->material, scene.find_material("blue"));
    EXPECT_TRUE(scene.object(0).blended_material != nullptr);
    EXPECT_EQ(painted->material, scene.find_material("blue"));
    EXPECT_TRUE(scene.object(1).part_materials.empty());
}

TEST_F(Instances, AGridIsTheSameOnEveryLoadAndFollowsItsSeed) {
    const auto grid = [&](int seed) {
        return load(scene_with(R"("definitions": {"b": {"material": "grey", "shape": {"type": "sphere", "radius": 0.2}}},
  "objects": [{"name": "g", "instance": "b", "transform": {"translate": [0, 0, -3]}, "grid": {"counts": [3, 2, 4],
    "spacing": [1, 1, 1], "jitter": 0.5, "rotate": {"angle": [0, 90]}, "scale": [0.5, 1], "materials": ["red", "blue"],
    "seed": )" + std::to_string(seed) + "}}]\n"));
    };
    const auto a = grid(1), b = grid(1), c = grid(2);
    ASSERT_EQ(a->scene->object_count(), 24u);
    EXPECT_EQ(a->scene->object(23).name, "g[23]");
    bool differs = false;
    std::set<std::string> materials;
    for (std::size_t i = 0; i < 24; ++i) {
        const auto id = std::uint32_t(i);
        const Transform ta = a->scene->object(id).to_world;
        EXPECT_EQ(ta.matrix(), b->scene->object(id).to_world.matrix());
        differs |= ta.matrix() != c->scene->object(id).to_world.matrix();
        materials.insert(a->scene->object(id).material == a->scene->find_material("red") ? "red" : "blue");
        // Placement 0 is the (-x, -y, -z) corner, moved by at most a quarter of the spacing, then by the transform.
        if (i == 0) {
            EXPECT_NEAR(ta.matrix()[0][3], -1.0, 0.25);
            EXPECT_NEAR(ta.matrix()[1][3], -0.5, 0.25);
            EXPECT_NEAR(ta.matrix()[2][3], -1.5 - 3.0, 0.25);
        }
    }
    EXPECT_TRUE(differs) << "another seed, other placements";
    EXPECT_EQ(materials.size(), 2u);
}

// Each emissive placement is an area light of its own, whose samples lie on the placed copy, and a hit on the copy
// finds that light.
TEST_F(Instances, EmissivePlacementsAreSampledAsLights) {
    const auto loaded = load(scene_with(R"("definitions": {"lamp": {"material": {"type": "emissive", "radiance": 2},
    "shape": {"type": "mesh", "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]]}}},
  "objects": [{"instance": "lamp", "placements": [{}, {"transform": {"translate": [2, 0, 0]}}]}]
)"));
    const RenderScene& scene = *loaded->scene;
    const BuildStatistics& build = scene.build_statistics();
    EXPECT_EQ(build.unsampled_emitters, 0u);
    EXPECT_EQ(build.area_lights, 2u);
    EXPECT_TRUE(scene.emission_can_be_hit());
    for (std::uint32_t id = 0; id < 2; ++id) {
        const Light* light = scene.object(id).area_light.light;
        ASSERT_NE(light, nullptr);
        EXPECT_FLOAT_EQ(scene.object(id).area_light.probability, 0.5f);  // two equal lamps
        const Vec3f from(0.25f + 2.0f * float(id), 0.25f, 3);
        const LightSample sample = light->sample(from, {0.3f, 0.4f});
        ASSERT_GT(sample.pdf, 0);
        const Vec3f on = from + sample.direction * sample.distance;
        EXPECT_NEAR(on.z, 0, 1e-5);
        EXPECT_GE(on.x, 2.0f * float(id) - 1e-5f);
        EXPECT_LE(on.x, 2.0f * float(id) + 1 + 1e-5f);
        const std::optional<SurfaceHit> hit = scene.intersect({from, {0, 0, -1}, 0, 10}, RayKind::Camera);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->object->area_light.light, light);
    }
}

// Emitters found by rays carry the probability with which next-event estimation chooses their light (for the MIS
// weight of a hit on them): the one choose_light reports, in proportion to the lights' powers.
TEST_F(Instances, EmittersCarryTheProbabilityOfChoosingTheirLight) {
    const auto loaded = load(scene_with(R"("lights": [{"type": "environment", "radiance": 0.5}],
  "objects": [
    {"material": {"type": "emissive", "radiance": 1},
     "shape": {"type": "mesh", "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]]}},
    {"material": {"type": "emissive", "radiance": 3},
     "shape": {"type": "mesh", "positions": [[2, 0, 0], [3, 0, 0], [2, 1, 0]], "triangles": [[0, 1, 2]]}}]
)"));
    const RenderScene& scene = *loaded->scene;
    ASSERT_EQ(scene.infinite_lights().size(), 1u);
    const LightChoice dim = scene.object(0).area_light, bright = scene.object(1).area_light;
    const LightChoice environment = scene.infinite_lights()[0];
    ASSERT_TRUE(dim.light && bright.light && environment.light);
    EXPECT_NEAR(bright.probability, 3 * dim.probability, 1e-6f);
    EXPECT_GT(environment.probability, 0);
    EXPECT_NEAR(dim.probability + bright.probability + environment.probability, 1, 1e-6f);
    for (float u = 0.0005f; u < 1; u += 0.001f) {
        const LightChoice chosen = scene.choose_light(u);
        const LightChoice& carried = chosen.light == dim.light      ? dim
                                     : chosen.light == bright.light ? bright
                                                                    : environment;
        ASSERT_EQ(chosen.light, carried.light) << u;
        EXPECT_EQ(chosen.probability, carried.probability) << u;
    }
}

struct BadInstances {
    std::string name, top_level;
    int line, column;
    std::string field, problem;
};

class BadInstanceInput : public Instances, public ::testing::WithParamInterface<BadInstances> {};

TEST_P(BadInstanceInput, IsRefusedAtItsPosition) {
    const BadInstances& c = GetParam();
    const std::string path = dir_.write("scene.json", scene_with(c.top_level)).string();
    std::string prefix = path + ":" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": " + c.field + ": ";
    testing::expect_input_error([&] { load_scene(path); }, path, c.line, c.column, c.field, prefix + c.problem);
}

const std::string kBall = R"({"material": "grey", "shape": {"type": "sphere", "radius": 1}})";

INSTANTIATE_TEST_SUITE_P(
    Cases, BadInstanceInput,
    ::testing::Values(
        BadInstances{"UnknownDefinition", R"("definitions": {"ball": )" + kBall + R"(},
"objects": [{"instance": "bal"}]
)", 6, 26, "objects[0].instance", "unknown definition \"bal\" (did you mean \"ball\"?)"},
        BadInstances{"NoDefinitions", R"("objects": [{"instance": "ball"}]
)", 5, 26, "objects[0].instance", "unknown definition \"ball\"; the scene has no \"definitions\""},
        BadInstances{"PlacesItself", R"("definitions": {"a": {"objects": [{"instance": "b"}]},
  "b": {"objects": [{"instance": "a"}]}},
"objects": [{"instance": "a"}]
)", 6, 34, "definitions.b.objects[0].instance", "definition \"a\" places itself: a -> b -> a"},
        BadInstances{"TooDeep", R"("definitions": {"d0": {"objects": [{"instance": "d1"}]}, "d1": {"objects": [{"instance": "d2"}]},
 "d2": {"objects": [{"instance": "d3"}]}, "d3": {"objects": [{"instance": "d4"}]}, "d4": {"objects": [{"instance": "d5"}]},
 "d5": {"objects": [{"instance": "d6"}]}, "d6": {"objects": [{"instance": "d7"}]}, "d7": {"objects": [{"instance": "d8"}]},
 "d8": {"objects": [{"instance": "d9"}]}, "d9": {"objects": [{"instance": "e0"}]}, "e0": {"objects": [{"instance": "e1"}]},
 "e1": {"objects": [{"instance": "e2"}]}, "e2": {"objects": [{"instance": "e3"}]}, "e3": {"objects": [{"instance": "e4"}]},
 "e4": {"objects": [{"instance": "e5"}]}, "e5": {"objects": [{"instance": "e6"}]}, "e6": )" + kBall + R"(},
"objects": [{"instance": "d0"}]
)", 10, 75, "definitions.e5.objects[0].instance",
                      "definitions nest more than 16 deep: d0 -> d1 -> d2 -> d3 -> d4 -> d5 -> d6 -> d7 -> d8 -> d9 -> "
                      "e0 -> e1 -> e2 -> e3 -> e4 -> e5 -> e6"},
        BadInstances{"ShapeAndInstance", R"("definitions": {"ball": )" + kBall + R"(},
"objects": [{"instance": "ball", "shape": {"type": "sphere"}}]
)", 6, 43, "objects[0].shape", "an object has a \"shape\" or places an \"instance\", not both"},
        BadInstances{"EmptyGroup", R"("definitions": {"g": {"objects": []}},
"objects": [{"instance": "g"}]
)", 5, 34, "definitions.g.objects", "a group needs at least one object"},
        BadInstances{"DefinitionOfNeither", R"("definitions": {"g": {"material": "grey"}},
"objects": [{"instance": "g"}]
)", 5, 22, "definitions.g",
                     "a definition has a \"shape\" (with its \"material\") or \"objects\" (a group), one of the two"},
        BadInstances{"PlacementsAndGrid", R"("definitions": {"ball": )" + kBall + R"(},
"objects": [{"instance": "ball", "placements": [], "grid": {"counts": [1, 1, 1], "spacing": [1, 1, 1]}}]
)", 6, 60, "objects[0].grid", "an object places its copies by \"placements\" or by a \"grid\", not both"},
        BadInstances{"FractionalCount", R"("definitions": {"ball": )" + kBall + R"(},
"objects": [{"instance": "ball", "grid": {"counts": [1.5, 1, 1], "spacing": [1, 1, 1]}}]
)", 6, 53, "objects[0].grid.counts", "expected whole numbers of placements along x, y and z"},
        BadInstances{"TooManyInAGrid", R"("definitions": {"ball": )" + kBall + R"(},
"objects": [{"instance": "ball", "grid": {"counts": [4096, 4096, 1], "spacing": [1, 1, 1]}}]
)", 6, 53, "objects[0].grid.counts", "a grid places at most 4194304 copies (asked: 16777216)"},
        BadInstances{"TooManyObjectsFromAGroup", R"("definitions": {"ball": )" + kBall + R"(,
  "g": {"objects": [{"instance": "ball", "grid": {"counts": [64, 64, 64], "spacing": [1, 1, 1]}}]}},
"objects": [{"instance": "g", "grid": {"counts": [2048, 1, 1], "spacing": [1, 1, 1]}}]
)", 7, 50, "objects[0].grid.counts",
                     "these placements add 536870912 objects (2048 placements of 262144 parts); at most 16777216 are allowed"},
        BadInstances{"UnknownOverride", R"("definitions": {"ball": )" + kBall + R"(},
"objects": [{"instance": "ball", "placements": [{"material": "gren"}]}]
)", 6, 62, "objects[0].placements[0].material",
                     "unknown material \"gren\" (did you mean \"grey\"?); defined: blue, grey, red"},
        BadInstances{"PlacementBeyondTheWorld", R"("definitions": {"ball": )" + kBall + R"(},
"objects": [{"instance": "ball", "placements": [{"transform": {"translate": [1e19, 0, 0]}}]}]
)", 6, 63, "objects[0].placements[0].transform",
                     "the shape, transformed, lies beyond 1e18 from the origin (every coordinate of the scene must be within [-1e18, 1e18])"}),
    [](const ::testing::TestParamInfo<BadInstances>& info) { return info.param.name; });

TEST_F(Instances, PlacementsAreChargedToTheMemoryLimit) {
    SceneOverrides overrides;
    overrides.max_memory_bytes = 64u << 20;
    const std::string path = dir_.write("scene.json", scene_with(R"("definitions": {"ball": )" + kBall + R"(},
"objects": [{"instance": "ball", "grid": {"counts": [1000, 100, 10], "spacing": [1, 1, 1]}}]
)")).string();
    try {
        load_scene(path, overrides);
        ADD_FAILURE() << "no error";
    } catch (const InputError& error) {
        EXPECT_EQ(error.field(), "objects[0].grid.counts");
        EXPECT_NE(std::string(error.what()).find("1000000 placed objects"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace isotrace
