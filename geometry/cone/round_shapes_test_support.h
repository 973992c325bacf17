#pragma once
// What the tests of the round shapes (cylinder, cone, torus) share: a scene around one shape's JSON, the loop over
// bad inputs, hits through a transformed scene against the shape's own solver in object space, the bounds of an
// exact distance field, and samples that a ray aimed back along their normal hits.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <string>

#include "geometry/csg/csg_test_support.h"
#include "geometry/mesh/mesh_test_support.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/scene/render_scene.h"

namespace isotrace::round_test {

// A scene whose only object has `shape` as its shape, written on line 4.
inline std::string scene_with_shape(const std::string& shape) {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"material": "m", "shape": )" +
           shape + "}]}";
}

struct BadInput {
    const char* shape;
    const char* where;  // in the message: the JSON path of the key at fault, or the text of the error
};

// Each shape fails to load with an InputError that names `where` and line 4 of its file.
inline void expect_input_errors(std::span<const BadInput> cases) {
    mesh_test::ScratchDirectory dir;
    for (const BadInput& c : cases) {
        const std::string path = dir.write("s.json", scene_with_shape(c.shape));
        const std::string message = mesh_test::input_error_message([&] { load_scene(path); });
        EXPECT_NE(message.find(c.where), std::string::npos) << c.shape << ": " << message;
        EXPECT_NE(message.find(path + ":4:"), std::string::npos) << c.shape << ": " << message;
    }
}

// A crossing of the shape in its own space: where, and the outward normal there.
struct ObjectHit {
    double t;
    Vec3d normal;
};

// Random float rays from within 6 units (in object space) of `target_centre` towards points near it, through
// `scene` (the shape placed by `to_world`): the hit is the first crossing `first_hits(o, d)` gives ahead of the
// origin in object space (t is unchanged by an affine map), with the normal carried by the inverse transpose.
// Rays with a crossing within 1e-3 of their origin are skipped. Returns how many rays hit.
inline int expect_hits_as_in_object_space(
    const RenderScene& scene, const Transform& to_world, const Vec3d& target_centre, unsigned seed,
    const std::function<std::vector<ObjectHit>(const Vec3d&, const Vec3d&)>& crossings) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    const auto jitter = [&](double scale) { return Vec3d(unit(random), unit(random), unit(random)) * scale; };
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3d o(Vec3f(to_world.point(target_centre + jitter(6))));
        const Vec3d d(Vec3f(to_world.point(target_centre + jitter(1)) - o));
        const Vec3d oo = to_world.inverse().point(o), od = to_world.inverse().vector(d);
        std::optional<ObjectHit> first;
        bool near_origin = false;
        for (const ObjectHit& c : crossings(oo, od)) {
            near_origin = near_origin || std::abs(c.t) < 1e-3;
            if (c.t > 0 && !first) first = c;
        }
        if (near_origin) continue;
        const auto hit = scene.intersect(csg_test::make_ray(o, d), RayKind::Camera);
        EXPECT_EQ(hit.has_value(), first.has_value()) << i;
        if (!hit || !first) continue;
        ++hits;
        EXPECT_NEAR(hit->t, first->t, 1e-5 * first->t) << i;
        csg_test::expect_near(hit->geometric_normal, normalize(to_world.normal(first->normal)), 1e-5,
                              "normal of ray " + std::to_string(i));
    }
    return hits;
}

// value_range and slope_range hold every value and directional slope sampled in random boxes within `spread` of
// `centre`, and the value range is no wider than the box's diagonal.
inline void expect_distance_bounds_hold(const ImplicitField& field, const Vec3d& centre, double spread, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1);
    for (int b = 0; b < 50; ++b) {
        const Vec3d corner = centre + Vec3d(unit(random), unit(random), unit(random)) * spread;
        const Vec3d size = Vec3d(fraction(random), fraction(random), fraction(random)) * (0.25 * spread);
        const IntervalBox box{{corner.x, corner.x + size.x}, {corner.y, corner.y + size.y}, {corner.z, corner.z + size.z}};
        const Vec3d direction(unit(random), unit(random), unit(random));
        const Interval values = field.value_range(box), slopes = field.slope_range(box, direction);
        for (int s = 0; s < 50; ++s) {
            const Vec3d p = corner + Vec3d(size.x * fraction(random), size.y * fraction(random), size.z * fraction(random));
            EXPECT_TRUE(values.contains(field.value(p)));
            EXPECT_TRUE(slopes.contains(dot(field.gradient(p), direction)));
        }
        EXPECT_LE(values.width(), length(size) * (1 + 1e-12));  // as tight as a Lipschitz bound gets
    }
}

// 500 samples of `shape` (baked into `scene`): pdf_area · area = 1, unit normals, and a ray from 0.01 along the
// normal back towards the point hits it there with that normal.
inline void expect_samples_hit_back(const RenderScene& scene, const Shape& shape,
                                    const std::function<std::array<float, 2>(std::uint32_t)>& u_sample) {
    for (std::uint32_t i = 0; i < 500; ++i) {
        const SurfaceSample s = shape.sample_surface(u_sample(i));
        EXPECT_NEAR(s.pdf_area * shape.surface_area(), 1.0, 1e-6);
        EXPECT_NEAR(length(s.normal), 1.0f, 1e-6f);
        Ray ray;
        ray.origin = s.position + s.normal * 0.01f;
        ray.direction = -s.normal;
        ray.t_far = 1;
        const auto hit = scene.intersect(ray, RayKind::Camera);
        ASSERT_TRUE(hit) << i;
        EXPECT_NEAR(hit->t, 0.01f, 1e-4f) << i;
        EXPECT_NEAR(dot(hit->geometric_normal, s.normal), 1.0f, 1e-4f) << i;
    }
}

}  // namespace isotrace::round_test
