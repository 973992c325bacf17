#include "renderer/params/world_limit.h"

#include <cmath>

namespace isotrace {

bool within_world(const Vec3d& p) {
    // Written so that NaN fails every comparison.
    return std::abs(p.x) <= kWorldLimit && std::abs(p.y) <= kWorldLimit && std::abs(p.z) <= kWorldLimit;
}

std::string beyond_world_problem(const std::string& what) {
    return what + " lies beyond 1e18 from the origin (every coordinate of the scene must be within [-1e18, 1e18])";
}

Vec3d world_point(const SceneNode& node, const std::string& key) {
    const Vec3d p = node.vec3(key);
    if (!within_world(p)) node.fail_at(key, beyond_world_problem("the point"));
    return p;
}

NumberRange world_length(bool allow_zero) { return {0, kWorldLimit, !allow_zero, false}; }

Vec3d unit_direction(const SceneNode& node, const Vec3d& v, const std::string& what) {
    const double largest = max_component(abs(v));
    if (!(largest > 0) || !std::isfinite(largest)) node.fail(what + " must be a finite, non-zero vector");
    return normalize(v / largest);
}

Vec3d unit_direction(const SceneNode& node, const std::string& key) {
    const Vec3d v = node.vec3(key);
    return unit_direction(*node.optional_value(key), v, "the direction");
}

void check_reach_within_world(const SceneNode& node, const std::string& key, const Transform& to_world,
                              double radius, const std::string& what) {
    const double reach = max_component(abs(to_world.point(Vec3d(0, 0, 0)))) + radius * to_world.linear_norm();
    if (!(reach <= kWorldLimit)) node.fail_at(key, beyond_world_problem(what));
}

}  // namespace isotrace
