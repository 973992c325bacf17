// Pinhole or thin-lens perspective camera. The camera looks down -z of its own frame, y up.
#include <cmath>
#include <numbers>

#include "renderer/core/enum_names.h"
#include "renderer/params/world_limit.h"
#include "renderer/plugin/camera.h"
#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

// The image side that "fov" spans.
enum class FovAxis { X, Y, Diagonal, Smaller, Larger };
// The values of "fov_axis", the default first.
constexpr EnumName<FovAxis> kFovAxisNames[] = {{FovAxis::X, "x"},
                                               {FovAxis::Y, "y"},
                                               {FovAxis::Diagonal, "diagonal"},
                                               {FovAxis::Smaller, "smaller"},
                                               {FovAxis::Larger, "larger"}};

class PerspectiveCamera final : public Camera {
public:
    PerspectiveCamera(const Transform& to_world, const RasterSize& raster, double fov_degrees,
                      FovAxis fov_axis, double aperture_radius, double focus_distance)
        : Camera(to_world),
          raster_(raster),
          aperture_radius_(float(aperture_radius)),
          focus_distance_(float(focus_distance)),
          pinhole_origin_(Vec3f(to_world.point(Vec3d(0, 0, 0)))) {
        const double tan_half = std::tan(fov_degrees * std::numbers::pi / 360.0);
        const double w = raster.width, h = raster.height;
        FovAxis axis = fov_axis;
        if (axis == FovAxis::Smaller) axis = w <= h ? FovAxis::X : FovAxis::Y;
        if (axis == FovAxis::Larger) axis = w >= h ? FovAxis::X : FovAxis::Y;
        if (axis == FovAxis::X) {
            half_width_ = tan_half;
            half_height_ = tan_half * h / w;
        } else if (axis == FovAxis::Y) {
            half_height_ = tan_half;
            half_width_ = tan_half * w / h;
        } else {  // diagonal
            const double diagonal = std::hypot(w, h);
            half_width_ = tan_half * w / diagonal;
            half_height_ = tan_half * h / diagonal;
        }
        pixel_angle_ = float(2 * half_height_ / h);  // at the image centre; the cone ignores the lens
    }

    Ray generate_ray(float raster_x, float raster_y, std::array<float, 2> lens_u) const override {
        const double x = (2.0 * raster_x / raster_.width - 1.0) * half_width_;
        const double y = (1.0 - 2.0 * raster_y / raster_.height) * half_height_;
        Vec3d direction(x, y, -1);
        const Transform& to_world = camera_to_world();
        Ray ray;
        ray.origin = pinhole_origin_;
        if (aperture_radius_ > 0) {
            // Thin lens: rays through every lens point meet again on the plane of focus.
            const auto disk = square_to_uniform_disk_concentric(lens_u);
            const Vec3d origin(disk[0] * aperture_radius_, disk[1] * aperture_radius_, 0);
            direction = direction * double(focus_distance_) - origin;
            ray.origin = Vec3f(to_world.point(origin));
        }
        ray.direction = Vec3f(normalize(to_world.vector(direction)));
        ray.cone_spread = pixel_angle_;
        return ray;
    }

private:
    RasterSize raster_;
    double half_width_ = 1, half_height_ = 1;  // image-plane extent at distance 1
    float pixel_angle_ = 0;                     // a pixel's angular height: the rays' cone spread
    float aperture_radius_;
    float focus_distance_;
    Vec3f pinhole_origin_;  // the camera's position in the world: every pinhole ray's origin
};

std::unique_ptr<Camera> create(const SceneNode& node, const RasterSize& raster) {
    const Transform to_world = parse_camera_placement(node);
    const double fov = node.number_or("fov", 40.0, {0, 180, true, true});
    const FovAxis axis =
        enum_value(kFovAxisNames, node.choice_or("fov_axis", kFovAxisNames[0].name, enum_names(kFovAxisNames)));
    const double aperture = node.number_or("aperture_radius", 0.0, world_length(true));
    check_reach_within_world(node, "aperture_radius", to_world, aperture, "the lens");
    double focus = 1.0;
    if (node.has("focus_distance")) {
        focus = node.number("focus_distance", world_length());
    } else if (auto look_at = node.optional_object("look_at")) {
        focus = length(look_at->vec3("target") - look_at->vec3("eye"));
    } else if (aperture > 0) {
        node.fail("a thin-lens camera (aperture_radius > 0) needs \"focus_distance\" or \"look_at\"");
    }
    return std::make_unique<PerspectiveCamera>(to_world, raster, fov, axis, aperture, focus);
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(camera_registry, "perspective",
                         "pinhole/thin lens; fov (deg), fov_axis, aperture_radius, focus_distance, look_at|transform",
                         create)

}  // namespace isotrace
