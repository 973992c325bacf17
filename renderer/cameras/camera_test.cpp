// Cameras created through the registry: the perspective camera's aim, field of view on each axis and aspect
// handling, the thin lens's focus, the orthographic camera's parallel rays and width, and view_depth().
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "renderer/core/input_error.h"
#include "renderer/embree/embree_ray.h"
#include "renderer/params/json_document.h"
#include "renderer/params/scene_node.h"
#include "renderer/plugin/camera.h"

namespace isotrace {
namespace {

std::unique_ptr<Camera> make_camera(const std::string& json, RasterSize raster) {
    const JsonValue document = parse_json(json, "camera.json");
    const SceneNode node(document, "camera", std::make_shared<SceneFileContext>());
    return camera_registry().create(node, raster);
}

double angle_degrees(const Vec3d& a, const Vec3d& b) {
    const double c = dot(normalize(a), normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180 / std::numbers::pi;
}

void expect_vec_near(const Vec3f& actual, const Vec3d& expected, double tolerance, const std::string& what = "") {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

const Vec3d kEye(1, 2, 3);
const Vec3d kTarget(-2, 0.5, -1);
const char* kLookAt = R"("look_at": {"eye": [1, 2, 3], "target": [-2, 0.5, -1], "up": [0, 1, 0]})";

std::string perspective(const std::string& extra) {
    return std::string(R"({"type": "perspective", )") + kLookAt + (extra.empty() ? "" : ", " + extra) + "}";
}

// Camera frame of the look_at above, computed independently: forward, right, up.
struct Frame {
    Vec3d forward, right, up;
};
Frame frame() {
    const Vec3d forward = normalize(kTarget - kEye);
    const Vec3d right = normalize(cross(forward, Vec3d(0, 1, 0)));
    return {forward, right, cross(right, forward)};
}

TEST(PerspectiveCamera, CentrePixelRayPointsAtTheTarget) {
    for (RasterSize raster : {RasterSize{64, 48}, RasterSize{33, 71}}) {
        const auto camera = make_camera(perspective(R"("fov": 50)"), raster);
        const Ray ray = camera->generate_ray(raster.width / 2.0f, raster.height / 2.0f, {0.3f, 0.7f});
        expect_vec_near(ray.origin, kEye, 1e-6);
        expect_vec_near(ray.direction, normalize(kTarget - kEye), 1e-6);
        EXPECT_NEAR(length(ray.direction), 1.0, 1e-6);
        EXPECT_EQ(ray.t_near, 0.0f);
        EXPECT_EQ(ray.t_far, INFINITY);
    }
}

TEST(PerspectiveCamera, RasterAxesRunRightAndDown) {
    const Frame f = frame();
    const auto camera = make_camera(perspective(""), {40, 30});
    const Vec3d left(camera->generate_ray(0, 15, {}).direction), right(camera->generate_ray(40, 15, {}).direction);
    const Vec3d top(camera->generate_ray(20, 0, {}).direction), bottom(camera->generate_ray(20, 30, {}).direction);
    EXPECT_LT(dot(left, f.right), 0);
    EXPECT_GT(dot(right, f.right), 0);
    EXPECT_GT(dot(top, f.up), 0);
    EXPECT_LT(dot(bottom, f.up), 0);
    EXPECT_NEAR(dot(left, f.up), 0, 1e-6);
    EXPECT_NEAR(dot(top, f.right), 0, 1e-6);
}

TEST(PerspectiveCamera, FieldOfViewMapsToTheEdgesOfItsAxis) {
    const RasterSize raster{80, 50};  // landscape
    const double w = raster.width, h = raster.height;
    const Vec3d forward = normalize(kTarget - kEye);
    for (double fov : {10.0, 40.0, 90.0, 150.0}) {
        const double tan_half = std::tan(fov * std::numbers::pi / 360);
        struct Case {
            const char* axis;
            double half_width, half_height;  // image plane at distance 1
        };
        const double diagonal = std::hypot(w, h);
        const Case cases[] = {
            {"x", tan_half, tan_half * h / w},
            {"y", tan_half * w / h, tan_half},
            {"diagonal", tan_half * w / diagonal, tan_half * h / diagonal},
            {"larger", tan_half, tan_half * h / w},   // width is larger
            {"smaller", tan_half * w / h, tan_half},  // height is smaller
        };
        for (const Case& c : cases) {
            const auto camera = make_camera(perspective("\"fov\": " + std::to_string(fov) + R"(, "fov_axis": ")" +
                                                        c.axis + "\""),
                                            raster);
            const auto edge_angle = [&](float x, float y) {
                return angle_degrees(Vec3d(camera->generate_ray(x, y, {}).direction), forward);
            };
            const double expected_x = std::atan(c.half_width) * 180 / std::numbers::pi;
            const double expected_y = std::atan(c.half_height) * 180 / std::numbers::pi;
            const double expected_corner = std::atan(std::hypot(c.half_width, c.half_height)) * 180 / std::numbers::pi;
            const std::string what = std::string(c.axis) + " fov " + std::to_string(fov);
            EXPECT_NEAR(edge_angle(0, float(h / 2)), expected_x, 1e-4) << what;
            EXPECT_NEAR(edge_angle(float(w), float(h / 2)), expected_x, 1e-4) << what;
            EXPECT_NEAR(edge_angle(float(w / 2), 0), expected_y, 1e-4) << what;
            EXPECT_NEAR(edge_angle(float(w / 2), float(h)), expected_y, 1e-4) << what;
            EXPECT_NEAR(edge_angle(0, 0), expected_corner, 1e-4) << what;
            EXPECT_NEAR(edge_angle(float(w), float(h)), expected_corner, 1e-4) << what;
        }
        // The named axis spans exactly the field of view.
        const auto x_camera = make_camera(perspective("\"fov\": " + std::to_string(fov)), raster);
        EXPECT_NEAR(angle_degrees(Vec3d(x_camera->generate_ray(0, 25, {}).direction),
                                  Vec3d(x_camera->generate_ray(80, 25, {}).direction)),
                    fov, 1e-4);
    }
}

TEST(PerspectiveCamera, PixelsAreSquareForAnyAspect) {
    const Frame f = frame();
    for (RasterSize raster : {RasterSize{100, 20}, RasterSize{20, 100}, RasterSize{37, 37}}) {
        for (const char* axis : {"x", "y", "diagonal"}) {
            const auto camera = make_camera(perspective(R"("fov": 60, "fov_axis": ")" + std::string(axis) + "\""), raster);
            // Points on the plane at distance 1 in front of the camera, one pixel right and one pixel down.
            const auto on_plane = [&](float x, float y) {
                const Vec3d d(camera->generate_ray(x, y, {}).direction);
                return d / dot(d, f.forward);
            };
            const Vec3d centre = on_plane(raster.width / 2.0f, raster.height / 2.0f);
            const double step_x = length(on_plane(raster.width / 2.0f + 1, raster.height / 2.0f) - centre);
            const double step_y = length(on_plane(raster.width / 2.0f, raster.height / 2.0f + 1) - centre);
            EXPECT_NEAR(step_x / step_y, 1.0, 1e-5) << raster.width << "x" << raster.height << " " << axis;
        }
    }
}

TEST(PerspectiveCamera, ThinLensRaysThroughAPixelMeetOnThePlaneOfFocus) {
    const Frame f = frame();
    const double focus = length(kTarget - kEye);  // from look_at
    for (const std::string& extra : {std::string(R"("aperture_radius": 0.2)"),
                                     std::string(R"("aperture_radius": 0.05, "focus_distance": 2.5)")}) {
        const double distance = extra.find("focus_distance") != std::string::npos ? 2.5 : focus;
        const auto camera = make_camera(perspective(extra), {48, 32});
        const double aperture = extra.find("0.2") != std::string::npos ? 0.2 : 0.05;
        for (const auto& [px, py] : {std::pair{24.0f, 16.0f}, std::pair{3.5f, 30.25f}, std::pair{47.0f, 0.5f}}) {
            Vec3d meeting{};
            double spread = 0;
            for (int i = 0; i < 64; ++i) {
                const std::array<float, 2> lens{(i % 8 + 0.5f) / 8, (i / 8 + 0.5f) / 8};
                const Ray ray = camera->generate_ray(px, py, lens);
                const Vec3d o(ray.origin), d(ray.direction);
                EXPECT_NEAR(length(d), 1.0, 1e-6);
                // Origins lie on the lens disk: in the plane of the eye, within the aperture.
                EXPECT_NEAR(dot(o - kEye, f.forward), 0, 1e-6);
                EXPECT_LE(length(o - kEye), aperture * (1 + 1e-6));
                spread = std::max(spread, length(o - kEye));
                // Intersection with the plane of focus (perpendicular to the viewing axis).
                const double t = (distance - dot(o - kEye, f.forward)) / dot(d, f.forward);
                const Vec3d p = o + d * t;
                if (i == 0) meeting = p;
                EXPECT_NEAR(length(p - meeting), 0, 1e-5 * distance) << extra << " pixel " << px << ", " << py;
            }
            EXPECT_GT(spread, 0.5 * aperture);  // the lens samples really moved the origin
            // The common point is where the pinhole ray of the same pixel meets the plane.
            const auto pinhole = make_camera(perspective(""), {48, 32});
            const Ray ray = pinhole->generate_ray(px, py, {});
            const Vec3d d(ray.direction);
            const Vec3d expected = kEye + d * (distance / dot(d, f.forward));
            EXPECT_NEAR(length(meeting - expected), 0, 1e-5 * distance);
        }
    }
}

TEST(PerspectiveCamera, ThinLensWithoutFocusIsAnInputError) {
    const std::string json = R"({"type": "perspective", "transform": {"translate": [0, 0, 5]}, "aperture_radius": 0.1})";
    EXPECT_THROW(make_camera(json, {8, 8}), InputError);
    // A pinhole needs no focus, and look_at/transform are exclusive.
    EXPECT_NO_THROW(make_camera(R"({"type": "perspective", "transform": {"translate": [0, 0, 5]}})", {8, 8}));
    EXPECT_THROW(make_camera(std::string(R"({"type": "perspective", "transform": {"translate": [0, 0, 5]}, )") +
                                 kLookAt + "}",
                             {8, 8}),
                 InputError);
    EXPECT_THROW(make_camera(perspective(R"("fov": 180)"), {8, 8}), InputError);
    EXPECT_THROW(make_camera(perspective(R"("fov_axis": "z")"), {8, 8}), InputError);
}

TEST(OrthographicCamera, ParallelRaysThroughAWindowOfTheGivenWidth) {
    const Frame f = frame();
    const RasterSize raster{60, 40};
    const double width = 3.0, height = width * 40 / 60;
    const auto camera =
        make_camera(std::string(R"({"type": "orthographic", "width": 3, )") + kLookAt + "}", raster);
    for (const auto& [x, y] : {std::pair{0.0f, 0.0f}, std::pair{60.0f, 40.0f}, std::pair{30.0f, 20.0f},
                               std::pair{12.5f, 33.0f}}) {
        const Ray ray = camera->generate_ray(x, y, {0.9f, 0.1f});
        expect_vec_near(ray.direction, f.forward, 1e-6, "parallel");
        const Vec3d expected = kEye + f.right * ((x / 60.0 - 0.5) * width) + f.up * ((0.5 - y / 40.0) * height);
        expect_vec_near(ray.origin, expected, 1e-5, "origin at " + std::to_string(x) + ", " + std::to_string(y));
    }
    // The lens sample does nothing.
    const Ray a = camera->generate_ray(7, 9, {0, 0}), b = camera->generate_ray(7, 9, {0.99f, 0.5f});
    EXPECT_EQ(a.origin, b.origin);
    EXPECT_EQ(a.direction, b.direction);
}

TEST(OrthographicCamera, DefaultWidthIsTwo) {
    const auto camera = make_camera(R"({"type": "orthographic", "transform": {"translate": [0, 0, 5]}})", {10, 20});
    expect_vec_near(camera->generate_ray(0, 0, {}).origin, {-1, 2, 5}, 1e-6);
    expect_vec_near(camera->generate_ray(10, 20, {}).origin, {1, -2, 5}, 1e-6);
    expect_vec_near(camera->generate_ray(3, 3, {}).direction, {0, 0, -1}, 1e-7);
}

TEST(Camera, ViewDepthIsTheDistanceAlongTheViewingAxis) {
    const Frame f = frame();
    for (const std::string& json :
         {perspective(""), std::string(R"({"type": "orthographic", )") + kLookAt + "}"}) {
        const auto camera = make_camera(json, {16, 16});
        for (double depth : {0.5, 1.0, 7.25}) {
            for (const Vec3d& lateral : {Vec3d(0, 0, 0), f.right * 2.0 + f.up * -3.0, f.up * 0.5}) {
                const Vec3d p = kEye + f.forward * depth + lateral;
                EXPECT_NEAR(camera->view_depth(Vec3f(p)), depth, 1e-5) << json;
            }
        }
        EXPECT_NEAR(camera->view_depth(Vec3f(kEye - f.forward)), -1.0, 1e-5);  // behind the camera
        // A hit along a camera ray: depth = t * cos(angle to the axis).
        const Ray ray = camera->generate_ray(1.5f, 13.0f, {});
        const Vec3d hit = Vec3d(ray.origin) + Vec3d(ray.direction) * 4.0;
        EXPECT_NEAR(camera->view_depth(Vec3f(hit)), dot(hit - kEye, f.forward), 1e-5);
    }
}

// The camera's error for `json`: at `field`, naming the limit.
void expect_refused_at(const std::string& json, const std::string& field) {
    try {
        make_camera(json, {16, 12});
        ADD_FAILURE() << "accepted: " << json;
    } catch (const InputError& error) {
        EXPECT_EQ(error.field(), field) << json;
        const std::string message = error.what();
        EXPECT_TRUE(message.find("1e18") != std::string::npos || message.find("1e+18") != std::string::npos)
            << message;
    }
}

TEST(Camera, PlacementsAndExtentsBeyondTheFiniteWorldAreRefusedWhereTheyAreWritten) {
    const std::string at_origin = R"("look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]})";
    expect_refused_at(R"({"type": "perspective", "look_at": {"eye": [1e19, 0, 5], "target": [0, 0, 0]}})",
                      "camera.look_at.eye");
    expect_refused_at(R"({"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, -2e18, 0]}})",
                      "camera.look_at.target");
    expect_refused_at(R"({"type": "perspective", "transform": {"translate": [0, 0, 1e30]}})", "camera.transform");
    expect_refused_at(R"({"type": "orthographic", "transform": [{"translate": [0, 0, 1e17]}, {"scale": 1e3}]})",
                      "camera.transform");
    expect_refused_at(R"({"type": "perspective", "aperture_radius": 1e19, )" + at_origin + "}",
                      "camera.aperture_radius");
    expect_refused_at(R"({"type": "perspective", "aperture_radius": 1e18, )" + at_origin + "}",
                      "camera.aperture_radius");  // within the limit alone, beyond it around the eye
    expect_refused_at(R"({"type": "perspective", "aperture_radius": 0.1, "focus_distance": 1e300, )" + at_origin + "}",
                      "camera.focus_distance");
    expect_refused_at(R"({"type": "orthographic", "width": 1e30, )" + at_origin + "}", "camera.width");
    expect_refused_at(R"({"type": "orthographic", "width": 1.5e18, )" + at_origin + "}", "camera.width");
}

TEST(Camera, ExtremeValuesWithinTheLimitsMakeTraceableRays) {
    const std::string at_origin = R"("look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]})";
    for (const std::string& json : {
             R"({"type": "perspective", "fov": 1e-300, )" + at_origin + "}",
             R"({"type": "perspective", "fov": 179.99999999999997, )" + at_origin + "}",
             std::string(R"({"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [1e300, 1e300, 0]}})"),
             R"({"type": "perspective", "aperture_radius": 5e17, "focus_distance": 1e18, )" + at_origin + "}",
             std::string(R"({"type": "perspective", "look_at": {"eye": [1e18, -1e18, 1e18], "target": [-1e18, 1e18, -1e18]}})"),
             R"({"type": "orthographic", "width": 1e17, )" + at_origin + "}",
             R"({"type": "orthographic", "width": 1e-300, )" + at_origin + "}",
         }) {
        const auto camera = make_camera(json, {16, 12});
        for (float x : {0.0f, 7.5f, 16.0f})
            for (float y : {0.0f, 12.0f})
                for (float u : {0.0f, 0.999f})
                    EXPECT_TRUE(is_traceable(camera->generate_ray(x, y, {u, 1 - u}))) << json << " " << x << " " << y;
    }
}

}  // namespace
}  // namespace isotrace
