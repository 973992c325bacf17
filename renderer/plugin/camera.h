#pragma once
#include <array>

#include "renderer/core/ray.h"
#include "renderer/math/transform.h"
#include "renderer/plugin/registry.h"

namespace isotrace {

// Full raster size the camera maps onto (crop windows select a part of it).
struct RasterSize {
    int width = 0;
    int height = 0;
};

class Camera {
public:
    explicit Camera(const Transform& camera_to_world)
        : camera_to_world_(camera_to_world),
          eye_(camera_to_world.point(Vec3d(0, 0, 0))),
          forward_(normalize(camera_to_world.vector(Vec3d(0, 0, -1)))) {}
    virtual ~Camera() = default;

    // Ray through raster position (x right, y down, in pixels of the full raster) with lens sample u.
    virtual Ray generate_ray(float raster_x, float raster_y, std::array<float, 2> lens_u) const = 0;

    // Distance of a world point in front of the camera along its viewing axis (the depth AOV), in world units
    // also when the placement transform scales (camera-space −z would then be in camera units).
    float view_depth(const Vec3f& world_point) const { return float(dot(Vec3d(world_point) - eye_, forward_)); }
    const Transform& camera_to_world() const { return camera_to_world_; }

private:
    Transform camera_to_world_;
    Vec3d eye_, forward_;  // camera origin and unit viewing direction in the world
};

Registry<Camera, const RasterSize&>& camera_registry();

// Reads a camera's placement: "look_at": {"eye", "target", "up"} or "transform".
Transform parse_camera_placement(const SceneNode& node);

}  // namespace isotrace
