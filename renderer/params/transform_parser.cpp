#include "renderer/params/transform_parser.h"

#include <cstdio>
#include <functional>
#include <stdexcept>

namespace isotrace {
namespace {

// Rays reach object space in float arithmetic: an ill-conditioned transform (very unequal scales, a nearly flat
// matrix) or an extreme overall scale leaves them inaccurate or non-finite (Embree then asserts). The bounds and
// why: docs/decisions.md, "Ill-conditioned transforms".
constexpr double kMaxConditionNumber = 1e6;
constexpr double kMaxScale = 1e12;  // Frobenius norm of the linear part and of its inverse

std::string shortest(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

void check_conditioning(const SceneNode& node, const Transform& t) {
    if (!(t.condition_number() <= kMaxConditionNumber))
        node.fail("the transform is ill-conditioned (condition number " + shortest(t.condition_number()) +
                  ", at most 1e6 is supported): its scales are too unequal or its matrix is nearly flat");
    if (!(t.linear_norm() <= kMaxScale) || !(t.inverse_linear_norm() <= kMaxScale))
        node.fail("the transform scales by " +
                  shortest(t.linear_norm() > kMaxScale ? t.linear_norm() : 1 / t.inverse_linear_norm()) +
                  ", outside the supported range [1e-12, 1e12]");
}

Transform checked(const SceneNode& node, const std::function<Transform()>& make) {
    Transform t;
    try {
        t = make();
    } catch (const std::invalid_argument& error) {
        node.fail(error.what());
    }
    check_conditioning(node, t);
    return t;
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
    if (!value.json().is_array()) return checked(value, [&] { return parse_step(value); });
    Transform result;
    for (const SceneNode& step : value.elements()) result = parse_step(step) * result;
    check_conditioning(value, result);  // well-conditioned steps can compose to an ill-conditioned whole
    return result;
}

Transform parse_optional_transform(const SceneNode& parent, const std::string& key) {
    const auto value = parent.optional_value(key);
    return value ? parse_transform(*value) : Transform();
}

}  // namespace isotrace
