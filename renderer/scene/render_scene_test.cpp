// RenderScene as a whole: mapping hits back to objects when baked and instanced objects mix, build statistics,
// occlusion agreeing with intersection, secondary rays leaving a surface without re-hitting it, and flat meshes'
// hits completed without the shape.
#include "renderer/scene/render_scene.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>

#include "geometry/mesh/triangle_mesh_shape.h"
#include "geometry/sphere/sphere_shape.h"
#include "renderer/embree/embree_ray.h"
#include "renderer/math/lanes.h"

namespace isotrace {
namespace {

Ray ray_between(const Vec3f& origin, const Vec3f& direction) {
    Ray ray;
    ray.origin = origin;
    ray.direction = direction;
    return ray;
}

std::unique_ptr<Shape> unit_sphere() { return std::make_unique<SphereShape>(std::vector<Sphere>{{{0, 0, 0}, 1}}); }

std::unique_ptr<Shape> floor_quad() {
    TriangleMeshData mesh;
    mesh.positions = {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}};
    mesh.triangles = {{{0, 2, 1}}, {{0, 3, 2}}};
    return std::make_unique<TriangleMeshShape>(std::move(mesh));
}

SceneObject make_object(const std::string& name, std::unique_ptr<Shape> shape, const Transform& to_world,
                        const Material* material = nullptr) {
    SceneObject object;
    object.name = name;
    object.shape = std::move(shape);
    object.to_world = to_world;
    object.material = material;
    return object;
}

// Objects 0 (baked sphere), 1 (instanced ellipsoid), 2 (mesh), 3 (baked sphere) in one scene.
std::unique_ptr<RenderScene> mixed_scene() {
    auto scene = std::make_unique<RenderScene>();
    scene->add_object(make_object("left", unit_sphere(), Transform::translate({-3, 1, 0})));
    scene->add_object(make_object("squashed", unit_sphere(),
                                  Transform::translate({0, 1, 0}) * Transform::scale({1, 0.5, 1})));
    scene->add_object(make_object("floor", floor_quad(), Transform()));
    scene->add_object(make_object("right", unit_sphere(), Transform::translate({3, 1, 0}) * Transform::scale({0.5, 0.5, 0.5})));
    scene->commit();
    return scene;
}

TEST(RenderScene, HitsNameTheirObjectWhetherBakedOrInstanced) {
    const auto scene = mixed_scene();
    const Vec3f down(0, -1, 0);
    const struct {
        float x;
        std::uint32_t object;
        float t;
    } cases[] = {{-3, 0, 8}, {0, 1, 8.5f}, {3, 3, 8.5f}, {1.5f, 2, 10}};
    for (const auto& c : cases) {
        const auto hit = scene->intersect(ray_between({c.x, 10, 0}, down), RayKind::Camera);
        ASSERT_TRUE(hit) << c.x;
        EXPECT_EQ(hit->object_index, c.object) << c.x;
        EXPECT_NEAR(hit->t, c.t, 1e-5) << c.x;
        EXPECT_NEAR(hit->geometric_normal.y, 1.0f, 1e-5) << c.x;  // tops of spheres, and the floor's front
    }
}

TEST(RenderScene, BuildStatisticsCountObjectsPrimitivesAndInstances) {
    const auto scene = mixed_scene();
    const BuildStatistics& stats = scene->build_statistics();
    EXPECT_EQ(stats.objects, 4u);
    EXPECT_EQ(stats.instanced_objects, 1u);  // only the non-uniformly scaled sphere
    EXPECT_EQ(stats.primitives_by_type.at("sphere"), 3u);
    EXPECT_EQ(stats.primitives_by_type.at("triangle_mesh"), 2u);
    EXPECT_GE(stats.seconds, 0.0);
    const Bounds3f bounds = scene->bounds();
    EXPECT_NEAR(bounds.lower.x, -5, 1e-5);
    EXPECT_NEAR(bounds.upper.x, 5, 1e-5);
    EXPECT_NEAR(bounds.upper.y, 2, 1e-5);
}

TEST(RenderScene, MaterialsAreFoundByName) {
    RenderScene scene;
    class Grey final : public Material {
        Rgb albedo(const SurfaceHit&) const override { return Rgb(0.5f); }
    };
    const Material* grey = scene.add_material("grey", std::make_unique<Grey>());
    EXPECT_EQ(scene.find_material("grey"), grey);
    EXPECT_EQ(scene.find_material("gray"), nullptr);
    EXPECT_EQ(scene.material_names(), std::vector<std::string>{"grey"});
    scene.add_object(make_object("ball", unit_sphere(), Transform(), grey));
    scene.commit();
    EXPECT_EQ(scene.intersect(ray_between({0, 0, 5}, {0, 0, -1}), RayKind::Camera)->material, grey);
}

TEST(RenderScene, OcclusionAgreesWithIntersection) {
    const auto scene = mixed_scene();
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-6, 6);
    for (int i = 0; i < 2000; ++i) {
        const Vec3f origin{coordinate(random), 4, coordinate(random)};
        const Vec3f target{coordinate(random), -1, coordinate(random)};
        Ray ray = ray_between(origin, target - origin);
        ray.t_far = 1.0f;
        EXPECT_EQ(scene->occluded(ray), scene->intersect(ray, RayKind::Shadow).has_value()) << i;
    }
}

// A lone user primitive (a sphere baked into the scene, or one placed by a transform it cannot bake) is tested only
// by rays that reach its box, as every primitive among several is; the rays here hit the floor far from it.
TEST(RenderScene, ALoneUserPrimitiveIsTestedOnlyByRaysNearIt) {
    for (const Transform& placement : {Transform::translate({0, 1, 0}), Transform::scale({1, 0.5, 1})}) {
        RenderScene scene;
        scene.add_object(make_object("floor", floor_quad(), Transform()));
        scene.add_object(make_object("sphere", unit_sphere(), placement));
        scene.commit();
        const std::uint64_t before = counters::totals().geometry["sphere"].tests;
        for (int i = 0; i < 100; ++i) {
            const Ray down = ray_between({3 + 0.01f * float(i), 4, 3}, {0, -1, 0});
            ASSERT_TRUE(scene.intersect(down, RayKind::Camera).has_value());
            ASSERT_TRUE(scene.occluded(down));
        }
        EXPECT_EQ(counters::totals().geometry["sphere"].tests, before);
        const Ray at_sphere = ray_between({0, 4, 0}, {0, -1, 0});
        ASSERT_TRUE(scene.intersect(at_sphere, RayKind::Camera).has_value());
        EXPECT_EQ(scene.intersect(at_sphere, RayKind::Camera)->object->name, "sphere");
    }
}

// Rays Embree cannot trace: each would abort the process inside Embree (its ray.valid() assertion).
std::vector<Ray> untraceable_rays() {
    constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    const Ray down = ray_between({0, 4, 0}, {0, -1, 0});
    std::vector<Ray> rays(8, down);
    rays[0].origin.x = 1e19f;                  // beyond Embree's FLT_LARGE
    rays[1].origin.y = kInfinity;
    rays[2].direction = {0, 0, 0};
    rays[3].direction.z = kNan;
    rays[4].direction.x = 3e18f;
    rays[5].t_near = 2, rays[5].t_far = 1;     // inverted
    rays[6].t_near = -1;
    rays[7].t_far = kNan;
    return rays;
}

std::uint64_t untraceable_count() { return counters::totals().named["rays.untraceable"]; }

TEST(RenderScene, UntraceableRaysMissAndTheirShadowRaysAreBlocked) {
    const auto scene = mixed_scene();
    const Ray down = ray_between({0, 4, 0}, {0, -1, 0});
    ASSERT_TRUE(is_traceable(down));
    ASSERT_TRUE(scene->intersect(down, RayKind::Camera).has_value());
    const std::uint64_t before = untraceable_count();
    const std::vector<Ray> rays = untraceable_rays();
    for (std::size_t i = 0; i < rays.size(); ++i) {
        EXPECT_FALSE(is_traceable(rays[i])) << i;
        EXPECT_FALSE(scene->intersect(rays[i], RayKind::Secondary).has_value()) << i;
        EXPECT_TRUE(scene->occluded(rays[i])) << i;
    }
    EXPECT_EQ(untraceable_count() - before, 2 * rays.size());
}

// The packets' test in lanes says of each lane what the one-ray test says of its ray.
TEST(RenderScene, TraceableLanesAreTheRaysOwnTest) {
    std::vector<Ray> rays = untraceable_rays();
    rays.push_back(ray_between({0, 4, 0}, {0, -1, 0}));
    for (std::size_t traceable_lane = 0; traceable_lane < 8; ++traceable_lane) {
        std::vector<Ray> packet(rays.begin(), rays.begin() + 8);
        packet[traceable_lane] = rays.back();
        const auto field = [&](auto read) {
            FloatLanes lanes;
            for (std::size_t lane = 0; lane < std::size_t(kLanes); ++lane) lanes[lane] = read(packet[lane]);
            return lanes;
        };
        const IntLanes ok = traceable(field([](const Ray& r) { return r.origin.x; }),
                                      field([](const Ray& r) { return r.origin.y; }),
                                      field([](const Ray& r) { return r.origin.z; }),
                                      field([](const Ray& r) { return r.direction.x; }),
                                      field([](const Ray& r) { return r.direction.y; }),
                                      field([](const Ray& r) { return r.direction.z; }),
                                      field([](const Ray& r) { return r.t_near; }),
                                      field([](const Ray& r) { return r.t_far; }));
        for (std::size_t lane = 0; lane < 8; ++lane)
            EXPECT_EQ(ok[lane], is_traceable(packet[lane]) ? -1 : 0) << traceable_lane << " " << lane;
        EXPECT_EQ(lane_bits(ok), 1u << traceable_lane);
    }
}

TEST(RenderScene, UntraceableLanesOfPacketsMissAndAreBlocked) {
    RenderScene scene;
    scene.add_object(make_object("floor", floor_quad(), Transform()));
    scene.commit();
    const std::vector<Ray> bad = untraceable_rays();
    const Ray down = ray_between({0, 4, 0}, {0, -1, 0});
    for (std::size_t bad_lane = 0; bad_lane < 8; ++bad_lane) {
        std::array<Ray, 8> rays;
        rays.fill(down);
        rays[bad_lane] = bad[bad_lane];
        std::array<std::optional<SurfaceHit>, 8> hits;
        const std::uint64_t before = untraceable_count();
        scene.intersect(rays, 0xffu, RayKind::Camera, hits);
        const unsigned blocked = scene.occluded(rays, 0xffu);
        EXPECT_EQ(untraceable_count() - before, 2u) << bad_lane;
        for (std::size_t lane = 0; lane < 8; ++lane) {
            EXPECT_EQ(hits[lane].has_value(), lane != bad_lane) << bad_lane << " " << lane;
            EXPECT_EQ(blocked >> lane & 1u, 1u) << bad_lane << " " << lane;
        }
    }
}

// The path tracer's packet queries: every live lane gets what the query of its ray alone gives, bit for bit (user
// geometries, an instanced one and a mesh, answering packets lane by lane; a lone live lane as a one-ray query);
// lanes not live are left out (neither traced nor counted), untraceable ones miss and are blocked. Camera rays'
// packets are traced as coherent ones (another traversal in Embree), the others as incoherent ones: both kinds.
TEST(RenderScene, PacketQueriesAnswerEachLaneAsItsOwnQueryDoes) {
    const auto scene = mixed_scene();
    const std::vector<Ray> bad = untraceable_rays();
    std::mt19937 random(11);
    std::uniform_real_distribution<float> coordinate(-6, 6);
    int hits = 0;
    for (int round = 0; round < 200; ++round) {
        std::array<Ray, 8> rays;
        const Vec3f origin{coordinate(random), 4, coordinate(random)};  // alike, as a pixel's rays are
        for (std::size_t lane = 0; lane < 8; ++lane) {
            rays[lane] = ray_between(origin, Vec3f{coordinate(random), -1, coordinate(random)} - origin);
            rays[lane].t_far = round % 2 ? 1.0f : std::numeric_limits<float>::infinity();
        }
        if (round % 5 == 0) rays[std::size_t(round / 5 % 8)] = bad[std::size_t(round / 5 % 8)];
        const unsigned live = round % 3 == 0 ? 0b10110101u : round % 3 == 1 ? 0xFFu : 1u << (round / 3 % 8);
        const RayKind kind = round / 2 % 2 ? RayKind::Camera : RayKind::Secondary;
        std::array<std::optional<SurfaceHit>, 8> found;
        const std::uint64_t rays_before = counters::totals().total_rays();
        scene->intersect(rays, live, kind, found);
        EXPECT_EQ(counters::totals().total_rays() - rays_before, std::uint64_t(std::popcount(live)));
        const unsigned blocked = scene->occluded(rays, live);
        for (std::size_t lane = 0; lane < 8; ++lane) {
            SCOPED_TRACE("round " + std::to_string(round) + ", lane " + std::to_string(lane));
            if (!(live >> lane & 1u)) {
                EXPECT_FALSE(found[lane].has_value());
                EXPECT_FALSE(blocked >> lane & 1u);
                continue;
            }
            const std::optional<SurfaceHit> alone = scene->intersect(rays[lane], kind);
            ASSERT_EQ(found[lane].has_value(), alone.has_value());
            EXPECT_EQ(bool(blocked >> lane & 1u), scene->occluded(rays[lane]));
            if (!alone) continue;
            ++hits;
            EXPECT_EQ(std::bit_cast<std::uint32_t>(found[lane]->t), std::bit_cast<std::uint32_t>(alone->t));
            EXPECT_EQ(found[lane]->position, alone->position);
            EXPECT_EQ(found[lane]->geometric_normal, alone->geometric_normal);
            EXPECT_EQ(found[lane]->shading_normal, alone->shading_normal);
            EXPECT_EQ(found[lane]->uv, alone->uv);
            EXPECT_EQ(found[lane]->object_index, alone->object_index);
            EXPECT_EQ(found[lane]->primitive_id, alone->primitive_id);
            EXPECT_EQ(found[lane]->position_error, alone->position_error);
        }
    }
    EXPECT_GT(hits, 500);
}

TEST(RenderScene, SpawnedRaysDoNotRehitTheirOwnSurface) {
    // Rays leave points of a large, offset sphere in random directions of the outer hemisphere, including
    // grazing ones; none may hit the sphere again (a convex surface cannot be re-hit from outside).
    auto scene = std::make_unique<RenderScene>();
    scene->add_object(make_object("big", std::make_unique<SphereShape>(std::vector<Sphere>{{{100, 50, -30}, 20}}),
                                  Transform()));
    scene->commit();
    std::mt19937 random(3);
    std::uniform_real_distribution<float> unit(-1, 1);
    int tested = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3f towards = normalize(Vec3f{unit(random), unit(random), unit(random)});
        const auto hit = scene->intersect(ray_between(Vec3f(100, 50, -30) + towards * 60.0f, -towards), RayKind::Camera);
        ASSERT_TRUE(hit);
        Vec3f direction = normalize(Vec3f{unit(random), unit(random), unit(random)});
        if (dot(direction, hit->geometric_normal) < 0) direction = -direction;
        Ray leaving = ray_between(hit->spawn_origin(direction), direction);
        EXPECT_FALSE(scene->intersect(leaving, RayKind::Secondary)) << i;
        ++tested;
    }
    EXPECT_EQ(tested, 4000);
}

// A flat mesh's hits are completed from Embree's hit without asking the shape (Shape::hit_shading): uv must still
// be the barycentrics of the triangle as written, also after a mirroring bake reversed it, and the normal its
// counter-clockwise front. The floor's first triangle (corners 0, 2, 1) holds (2, 0, -1) at barycentrics 0.4 of
// corner 2 and 0.3 of corner 1; mirrored in x, the same corner point is (-2, 0, -1).
TEST(RenderScene, FlatMeshHitsKeepTheirUvAndFrontWhenMirrored) {
    for (const bool mirrored : {false, true}) {
        RenderScene scene;
        scene.add_object(make_object("floor", floor_quad(), mirrored ? Transform::scale({-1, 1, 1}) : Transform()));
        scene.commit();
        ASSERT_FALSE(scene.objects()[0].instanced);
        EXPECT_EQ(scene.objects()[0].hit_shading,
                  mirrored ? HitShading::EmbreeHitSwappedUv : HitShading::EmbreeHit);
        const float x = mirrored ? -2.0f : 2.0f;
        const auto hit = scene.intersect(ray_between({x, 1, -1}, {0, -1, 0}), RayKind::Camera);
        ASSERT_TRUE(hit.has_value()) << "mirrored " << mirrored;
        EXPECT_NEAR(hit->uv[0], 0.4f, 1e-6f) << "mirrored " << mirrored;
        EXPECT_NEAR(hit->uv[1], 0.3f, 1e-6f) << "mirrored " << mirrored;
        EXPECT_NEAR(hit->geometric_normal.y, 1.0f, 1e-6f) << "mirrored " << mirrored;
        EXPECT_NEAR(hit->shading_normal.y, 1.0f, 1e-6f) << "mirrored " << mirrored;
        EXPECT_NEAR(hit->t, 1.0f, 1e-6f);
    }
}

}  // namespace
}  // namespace isotrace
