#pragma once
// Checks of scene values against the finite world (kWorldLimit, renderer/core/ray.h): shapes, cameras, lights and
// object transforms are held to this one limit where the scene is read, each refused at its own position.
#include <string>

#include "renderer/core/ray.h"
#include "renderer/math/transform.h"
#include "renderer/math/vec3.h"
#include "renderer/params/scene_node.h"

namespace isotrace {

// Every component of `p` finite and at most kWorldLimit in magnitude.
bool within_world(const Vec3d& p);

// The problem to report for something (`what`) that reaches beyond the limit: "<what> lies beyond 1e18 ...".
std::string beyond_world_problem(const std::string& what);

// node[key] as a point within the limit; fails at its position otherwise.
Vec3d world_point(const SceneNode& node, const std::string& key);

// A length (radius, width, distance) that positions rays: in (0, kWorldLimit]; `allow_zero` makes it [0, ...].
NumberRange world_length(bool allow_zero = false);

// node[key] as a direction: finite, non-zero, returned at unit length (scaled before it is normalised, so that
// components near the double range do not overflow). Fails at its position otherwise.
Vec3d unit_direction(const SceneNode& node, const std::string& key);
// The same for a vector computed from the scene's values (a look-at's up, a target minus a position).
Vec3d unit_direction(const SceneNode& node, const Vec3d& v, const std::string& what);

// Fails at node[key] when a point within `radius` of to_world's origin, in the transform's own units (a lens, an
// orthographic window), can lie beyond the limit.
void check_reach_within_world(const SceneNode& node, const std::string& key, const Transform& to_world,
                              double radius, const std::string& what);

}  // namespace isotrace
