#include "renderer/scene/transform_parser.h"

#include <functional>
#include <stdexcept>

namespace isotrace {
namespace {

Transform checked(const SceneNode& node, const std::function<Transform()>& make) {
    try {
        return make();
    } catch (const std::invalid_argument& error) {
        node.fail(error.what());
    }
}

Transform rotation_of(const SceneNode& rotate) {
    if (rotate.json().is_array()) {
        const Vec3d degrees = rotate.as_vec3();
        return Transform::rotate({0, 0, 1}, degrees.z) * Transform::rotate({0, 1, 0}, degrees.y) *
               Transform::rotate({1, 0, 0}, degrees.x);
    }
    if (!rotate.json().is_object())
        rotate.fail("expected {\"axis\": [x, y, z], \"angle\": degrees} or [rx, ry, rz] in degrees");
    const Vec3d axis = rotate.vec3("axis");
    const double angle = rotate.number("angle");
    rotate.finish();
    return checked(rotate, [&] { return Transform::rotate(axis, angle); });
}

Transform parse_scale(const SceneNode& scale) {
    const Vec3d factors = scale.json().is_number() ? Vec3d(1, 1, 1) * scale.as_number() : scale.as_vec3();
    return checked(scale, [&] { return Transform::scale(factors); });
}

Transform parse_step(const SceneNode& step) {
    if (!step.json().is_object()) step.fail("expected a transform object");
    if (step.has("matrix")) {
        const std::vector<double> values = step.numbers("matrix", 16);
        step.finish();
        Transform::Matrix m{};
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = values[std::size_t(i)];
        return checked(*step.optional_value("matrix"), [&] { return Transform::from_matrix(m); });
    }
    Transform result;
    if (auto translate = step.optional_value("translate")) result = Transform::translate(translate->as_vec3());
    if (auto rotate = step.optional_value("rotate")) result = result * rotation_of(*rotate);
    if (auto scale = step.optional_value("scale")) result = result * parse_scale(*scale);
    step.finish();
    return result;
}

}  // namespace

Transform parse_rotation(const SceneNode& rotate) { return rotation_of(rotate); }

Transform parse_transform(const SceneNode& value) {
    if (!value.json().is_array()) return parse_step(value);
    Transform result;
    for (const SceneNode& step : value.elements()) result = parse_step(step) * result;
    return result;
}

Transform parse_optional_transform(const SceneNode& parent, const std::string& key) {
    const auto value = parent.optional_value(key);
    return value ? parse_transform(*value) : Transform();
}

}  // namespace isotrace
