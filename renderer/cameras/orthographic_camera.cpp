// Orthographic camera: parallel rays along -z of the camera frame through a width x height window.
#include <cmath>

#include "renderer/params/world_limit.h"
#include "renderer/plugin/camera.h"

namespace isotrace {
namespace {

class OrthographicCamera final : public Camera {
public:
    OrthographicCamera(const Transform& to_world, const RasterSize& raster, double width)
        : Camera(to_world),
          raster_(raster),
          half_width_(width / 2),
          half_height_(width / 2 * raster.height / raster.width),
          pixel_width_(float(width / raster.width * std::cbrt(std::abs(to_world.determinant())))) {}

    Ray generate_ray(float raster_x, float raster_y, std::array<float, 2>) const override {
        const Vec3d origin((2.0 * raster_x / raster_.width - 1.0) * half_width_,
                           (1.0 - 2.0 * raster_y / raster_.height) * half_height_, 0);
        Ray ray;
        ray.origin = Vec3f(camera_to_world().point(origin));
        ray.direction = Vec3f(normalize(camera_to_world().vector(Vec3d(0, 0, -1))));
        ray.cone_width = pixel_width_;
        return ray;
    }

private:
    RasterSize raster_;
    double half_width_, half_height_;
    float pixel_width_;  // in world units: the rays' cone width
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(camera_registry, "orthographic", "parallel projection; width (world units), look_at|transform",
                         [](const SceneNode& node, const RasterSize& raster) -> std::unique_ptr<Camera> {
                             const Transform to_world = parse_camera_placement(node);
                             const double width = node.number_or("width", 2.0, world_length());
                             const double half_diagonal = width / 2 * std::hypot(1.0, double(raster.height) / raster.width);
                             check_reach_within_world(node, "width", to_world, half_diagonal, "the view's window");
                             return std::make_unique<OrthographicCamera>(to_world, raster, width);
                         })

}  // namespace isotrace
