#include "geometry/sweep/sweep_spec.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "geometry/sweep/radius_measurement.h"
#include "renderer/params/transform_parser.h"

namespace isotrace {
namespace {

Quaternion rotation_of(const Transform& rotation) {
    return Quaternion::from_axes(rotation.vector(Vec3d(1, 0, 0)), rotation.vector(Vec3d(0, 1, 0)),
                                 rotation.vector(Vec3d(0, 0, 1)));
}

// The smallest rotation taking the z axis to `normal`.
Quaternion rotation_to(const Vec3d& normal) {
    const Vec3d n = normalize(normal);
    const Vec3d axis = cross(Vec3d(0, 0, 1), n);
    if (length(axis) < 1e-12) return n.z > 0 ? Quaternion::identity() : Quaternion::from_axis_angle({1, 0, 0}, 180);
    return Quaternion::from_axis_angle(axis, std::atan2(length(axis), n.z) * 180 / M_PI);
}

Quaternion parse_orientation(const SceneNode& key) {
    if (int(key.has("orientation")) + int(key.has("rotate")) + int(key.has("normal")) > 1)
        key.fail("give one of \"rotate\", \"orientation\" and \"normal\"");
    if (key.has("normal")) {
        const Vec3d normal = key.vec3("normal");
        if (!(length(normal) > 0)) key.fail_at("normal", "must not be zero");
        return rotation_to(normal);
    }
    if (const auto q = key.optional_value("orientation")) {
        const std::vector<double> v = key.numbers("orientation", 4);
        return {v[0], v[1], v[2], v[3]};  // checked for unit length by the sweep
    }
    if (const auto rotate = key.optional_value("rotate")) return rotation_of(parse_rotation(*rotate));
    return Quaternion::identity();
}

}  // namespace

SweepSpec parse_sweep_spec(const SceneNode& node) {
    SweepSpec spec{node, node.string_or("name", ""), {}, node.integer_or("radius_samples", 16, NumberRange::between(3, 512)),
                   node.boolean_or("relative", false), node.number_or("measured_radius_scale", 1, NumberRange::between(0.01, 100)),
                   node.choice_or("measure", "radii", {"radii", "circle"}) == "circle",
                   node.choice_or("spline", "cubic", {"cubic", "shape_preserving"}) == "cubic" ? SweepSpline::cubic
                                                                                         : SweepSpline::shape_preserving};
    for (const SceneNode& key : node.object_array("key_sections")) {
        KeySectionSpec k{key, key.vec3("center"), parse_orientation(key), {}};
        if (key.has("radii") && key.has("radius")) key.fail("give \"radii\" or \"radius\", not both");
        if (const auto radii = key.optional_value("radii")) {
            for (const SceneNode& r : radii->elements()) k.radii.push_back(r.as_number(NumberRange::positive()));
        } else if (key.has("radius")) {
            k.radii.assign(std::size_t(spec.radius_samples), key.number("radius", NumberRange::positive()));
        }
        key.finish();
        spec.keys.push_back(std::move(k));
    }
    if (spec.keys.size() < 2) node.fail("a sweep needs at least 2 key_sections, got " + std::to_string(spec.keys.size()));
    return spec;
}

bool SweepSpec::measures_radii() const {
    return std::any_of(keys.begin(), keys.end(), [](const KeySectionSpec& k) { return k.radii.empty(); });
}

std::vector<KeySection> SweepSpec::key_sections(const TriangleMeshData* mesh) const {
    std::vector<KeySection> keys;
    for (const KeySectionSpec& k : this->keys) keys.push_back({k.centre, k.orientation, k.radii});
    if (relative) {
        std::vector<RelativeKeySection> chain;
        for (const KeySection& k : keys) chain.push_back({k.centre, k.orientation, k.radii});
        keys = to_absolute(chain);
    }
    std::unique_ptr<RadiusProbe> probe;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (!keys[i].radii.empty()) continue;
        const SceneNode& key = this->keys[i].node;
        if (!mesh) key.fail("needs \"radii\" or \"radius\" here (there is no mesh to measure them on)");
        const double norm = keys[i].orientation.norm();
        if (!(std::abs(norm - 1) <= 1e-6)) key.fail("orientation: not a unit quaternion (|q| = " + std::to_string(norm) + ")");
        if (!probe) probe = std::make_unique<RadiusProbe>(*mesh);
        keys[i].radii = at_node(key, [&] { return probe->measure(keys[i].centre, keys[i].orientation, radius_samples); });
        const double largest = *std::max_element(keys[i].radii.begin(), keys[i].radii.end());
        for (double& r : keys[i].radii) r = (measure_circle ? largest : r) * measured_radius_scale;
    }
    return keys;
}

EditSpec parse_edit_spec(const SceneNode& node, bool hierarchy) {
    EditSpec spec{node, hierarchy ? node.string("sweep") : std::string(), hierarchy ? 1 : node.integer_or("level", 1, NumberRange::at_least(1)),
                  node.integer("key", NumberRange::at_least(0)), {}, {}};
    spec.edit.translate = node.vec3_or("translate", {0, 0, 0});
    if (const auto rotate = node.optional_value("rotate")) spec.edit.rotate = rotation_of(parse_rotation(*rotate));
    spec.edit.radius_scale = node.number_or("scale_radii", 1, NumberRange::positive());
    spec.edit.radius_offset = node.number_or("add_radius", 0);
    if (hierarchy && node.has("pull")) spec.pull = node.vec3("pull");
    node.finish();
    return spec;
}

}  // namespace isotrace
