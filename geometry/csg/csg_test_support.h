#pragma once
// Shared by the CSG, box and mesh-solid tests: solids built in code, scenes of one object, ray helpers, and an
// oracle that finds a composite's first boundary by classifying points instead of combining spans.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/box/box_shape.h"
#include "geometry/csg/csg_shape.h"
#include "geometry/sphere/sphere_shape.h"
#include "renderer/scene/render_scene.h"

namespace isotrace::csg_test {

inline std::unique_ptr<Shape> sphere(const Vec3d& centre, double radius) {
    return std::make_unique<SphereShape>(std::vector<Sphere>{{centre, radius}});
}

inline std::unique_ptr<Shape> box(const Vec3d& centre, const Vec3d& half_size) {
    return std::make_unique<BoxShape>(centre, half_size);
}

inline CsgChild child(std::unique_ptr<Shape> shape, const Transform& to_csg = {}, const std::string& material = "") {
    return {std::move(shape), to_csg, {material, {}, {}}};
}

// CSG of the given children (moved in).
template <class... Children>
std::unique_ptr<CsgShape> csg(CsgOperation operation, Children&&... children) {
    std::vector<CsgChild> list;
    (list.push_back(std::forward<Children>(children)), ...);
    return std::make_unique<CsgShape>(operation, std::move(list));
}

// Solid spans of a ball, counting the span queries, with a certainly_outside answer set by the test.
class CountingBall final : public Shape, public Solid {
public:
    CountingBall(const Vec3d& centre, double radius, bool claims_outside = false)
        : ball_(sphere(centre, radius)), claims_outside_(claims_outside) {}

    std::string type_name() const override { return "counting ball"; }
    std::size_t primitive_count() const override { return 1; }
    Bounds3f bounds() const override { return ball_->bounds(); }
    bool can_bake(const Transform&) const override { return true; }
    void bake(const Transform&) override {}  // placed by the identity only
    RTCGeometry create_geometry(RTCDevice) override { return nullptr; }

    void inside_spans(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max,
                      std::vector<InsideSpan>& spans, QueryScratch& scratch) const override {
        ++queries;
        dynamic_cast<const Solid&>(*ball_).inside_spans(origin, direction, t_min, t_max, spans, scratch);
    }
    bool certainly_outside(const Vec3d&, double) const override { return claims_outside_; }

    mutable int queries = 0;

private:
    std::unique_ptr<Shape> ball_;
    bool claims_outside_;
};

inline std::unique_ptr<RenderScene> scene_of(std::unique_ptr<Shape> shape, const Transform& to_world = {}) {
    auto scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.name = "solid";
    object.shape = std::move(shape);
    object.to_world = to_world;
    scene->add_object(std::move(object));
    scene->commit();
    return scene;
}

inline Ray make_ray(const Vec3d& o, const Vec3d& d, float t_near = 0, float t_far = INFINITY) {
    Ray ray;
    ray.origin = Vec3f(o);
    ray.direction = Vec3f(d);
    ray.t_near = t_near;
    ray.t_far = t_far;
    return ray;
}

// Every surface the ray meets, nearest first, by repeated nearest-hit queries that start just past the last hit.
inline std::vector<SurfaceHit> hit_sequence(const RenderScene& scene, Ray ray, float step = 1e-4f) {
    std::vector<SurfaceHit> hits;
    while (const auto hit = scene.intersect(ray, RayKind::Camera)) {
        hits.push_back(*hit);
        ray.t_near = hit->t + step;
        if (hits.size() > 64) break;  // a bug, reported by the caller's expectations
    }
    return hits;
}

inline void expect_near(const Vec3f& actual, const Vec3d& expected, double tolerance, const std::string& what) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

// Points in a solid, as a predicate (the oracle's description of a composite).
using Membership = std::function<bool(const Vec3d&)>;

inline Membership in_sphere(const Vec3d& centre, double radius) {
    return [=](const Vec3d& p) { return length(p - centre) < radius; };
}

// The first t in (t_near, t_far) among `candidates` (every surface crossing of the operands) where `inside`
// changes between t - delta and t + delta: the composite's nearest boundary, found without span lists.
inline std::optional<double> first_membership_change(const Vec3d& o, const Vec3d& d, std::vector<double> candidates,
                                                     const Membership& inside, double t_near = 0,
                                                     double t_far = INFINITY, double delta = 1e-7) {
    std::sort(candidates.begin(), candidates.end());
    for (double t : candidates) {
        if (!(t > t_near && t < t_far)) continue;
        if (inside(o + d * (t - delta)) != inside(o + d * (t + delta))) return t;
    }
    return std::nullopt;
}

}  // namespace isotrace::csg_test
