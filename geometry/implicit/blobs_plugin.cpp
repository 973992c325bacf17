// Scene plugin "blobs": a blob group of metaballs and metacubes, listed inline and/or produced by a seeded
// generator (large clouds come from a generator, never from megabytes of JSON).
#include <cmath>
#include <stdexcept>

#include "geometry/implicit/blob_group_shape.h"
#include "renderer/core/ray.h"
#include "renderer/sampling/hash.h"
#include "renderer/scene/transform_parser.h"

namespace isotrace {
namespace {

// Half-sizes: a number (cube) or [dx, dy, dz]; 0 = metaball.
Vec3d parse_half_size(const SceneNode& node) {
    const auto value = node.optional_value("half_size");
    if (!value) return {0, 0, 0};
    if (value->json().is_number()) {
        const double d = value->as_number(NumberRange::non_negative());
        return {d, d, d};
    }
    const Vec3d d = value->as_vec3();
    if (d.x < 0 || d.y < 0 || d.z < 0) value->fail("half-sizes must not be negative");
    return d;
}

Metacube make_element(const SceneNode& node, const OrientedBox& box, double radius, double weight) {
    try {
        return Metacube(box, radius, weight);
    } catch (const std::invalid_argument& error) {
        node.fail(error.what());
    }
}

Metacube parse_element(const SceneNode& node) {
    OrientedBox box;
    box.centre = node.vec3("center");
    box.half_size = parse_half_size(node);
    if (const auto rotate = node.optional_value("rotate")) {
        const Transform rotation = parse_rotation(*rotate);
        for (int k = 0; k < 3; ++k) {
            Vec3d unit(0, 0, 0);
            unit[k] = 1;
            box.axes[std::size_t(k)] = normalize(rotation.vector(unit));
        }
    }
    const double radius = node.number("radius", NumberRange::non_negative());
    const double weight = node.number_or("weight", 1.0);
    node.finish();
    return make_element(node, box, radius, weight);
}

// A uniform double in [0, 1) from (seed, element, field): reproducible on every platform, unlike the standard
// library's distributions.
double uniform(std::uint64_t seed, std::uint64_t element, std::uint64_t field) {
    return double(hash_combine(seed, element, field) >> 11) * 0x1p-53;
}

// "generate": {"count", "seed", "min": [x,y,z], "max": [x,y,z], "radius": [lo, hi], "weight": [lo, hi],
//              "half_size": [lo, hi]} — elements uniformly placed in the box with uniform parameters.
void generate_elements(const SceneNode& node, std::vector<Metacube>& elements) {
    const int count = node.integer("count", NumberRange::between(1, 100'000'000));
    const std::uint64_t seed = node.unsigned_or("seed", 0);
    const Vec3d lower = node.vec3("min"), upper = node.vec3("max");
    if (!(lower.x <= upper.x && lower.y <= upper.y && lower.z <= upper.z)) node.fail_at("max", "max must be >= min");
    const auto range = [&](const std::string& key, double fallback, NumberRange allowed) {
        if (!node.has(key)) return std::array<double, 2>{fallback, fallback};
        const auto v = node.numbers(key, 2, allowed);
        if (v[0] > v[1]) node.fail_at(key, "expected [low, high] with low <= high");
        return std::array<double, 2>{v[0], v[1]};
    };
    const auto radius = range("radius", 0.1, NumberRange::positive());
    const auto weight = range("weight", 1.0, {});
    const auto half_size = range("half_size", 0.0, NumberRange::non_negative());
    node.finish();
    try {
        node.context().memory->charge(saturating_product({std::uint64_t(count), BlobGroup::kPeakBytesPerElement}),
                                      "a blob group of " + std::to_string(count) + " generated elements");
    } catch (const InputError& error) {
        node.fail_at("count", error.problem());
    }
    const auto lerp = [](const std::array<double, 2>& r, double u) { return r[0] + (r[1] - r[0]) * u; };
    elements.reserve(elements.size() + std::size_t(count));
    for (int i = 0; i < count; ++i) {
        OrientedBox box;
        for (int k = 0; k < 3; ++k) box.centre[k] = lower[k] + (upper[k] - lower[k]) * uniform(seed, i, k);
        const double d = lerp(half_size, uniform(seed, i, 3));
        box.half_size = {d, d, d};
        elements.push_back(make_element(node, box, lerp(radius, uniform(seed, i, 4)), lerp(weight, uniform(seed, i, 5))));
    }
}

std::unique_ptr<Shape> create(const SceneNode& node) {
    const std::vector<std::string> names(field_function_names().begin(), field_function_names().end());
    const std::string field = node.choice_or("field", "kim", names);
    const double sharpness = node.number_or("sharpness", 4.0, NumberRange::positive());
    const double threshold = node.number_or("threshold", 0.5, NumberRange::positive());
    std::vector<Metacube> elements;
    for (const SceneNode& element : node.object_array("elements")) elements.push_back(parse_element(element));
    if (const auto generate = node.optional_object("generate")) generate_elements(*generate, elements);
    if (elements.empty()) node.fail("a blob group needs \"elements\" or \"generate\"");
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const WorldBounds b = elements[i].support_bounds();
        if (std::max(max_component(abs(b.lower)), max_component(abs(b.upper))) > kWorldLimit)
            node.fail("element " + std::to_string(i) + " extends beyond 1e18 from the origin");
    }
    return std::make_unique<BlobGroupShape>(BlobGroup(std::move(elements), make_field_function(field, sharpness), threshold));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "blobs",
                         "blended metaballs/metacubes; field (kim, wyvill, murakami, nishimura, blinn), threshold "
                         "(0.5), sharpness (blinn), elements: [{center, radius, weight, half_size, rotate}], "
                         "generate: {count, seed, min, max, radius, weight, half_size}",
                         create)

}  // namespace isotrace
