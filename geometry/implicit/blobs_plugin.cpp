// Scene plugin "blobs": a blob group of metaballs and metacubes, listed inline and/or produced by a seeded
// generator (large clouds come from a generator, never from megabytes of JSON).
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "geometry/csg/material_reference_parser.h"
#include "geometry/implicit/blob_group_shape.h"
#include "renderer/core/ray.h"
#include "renderer/params/transform_parser.h"
#include "renderer/sampling/hash.h"

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

// The elements' materials as they are read: the parts in order of first appearance (part 0, no name: the object's
// material), and each element's part, kept only from the first element that names one (plain groups pay nothing).
class ElementMaterials {
public:
    // The part of `reference` (a new part for a name not seen before).
    std::uint32_t part_of(const MaterialReference& reference) {
        if (reference.name.empty()) return 0;
        const auto [found, added] = index_.try_emplace(reference.name, std::uint32_t(parts_.size()));
        if (added) parts_.push_back(reference);
        return found->second;
    }
    // Records the part of element `element` (elements are added in order).
    void assign(std::size_t element, std::uint32_t part) {
        if (part == 0 && element_parts_.empty()) return;
        element_parts_.resize(element, 0);
        element_parts_.push_back(part);
    }
    // Whether the elements' parts are kept (some element so far named a material).
    bool keeps_parts() const { return !element_parts_.empty(); }
    // Room for the parts of `elements` elements in all, so that a large generated group grows them once.
    void reserve(std::size_t elements) { element_parts_.reserve(elements); }
    BlobMaterials finish(std::size_t elements) {
        if (element_parts_.empty()) return {};
        element_parts_.resize(elements, 0);
        return BlobMaterials(std::move(parts_), std::move(element_parts_));
    }

private:
    std::vector<MaterialReference> parts_{MaterialReference{}};
    std::map<std::string, std::uint32_t> index_;
    std::vector<std::uint32_t> element_parts_;
};

Metacube parse_element(const SceneNode& node, std::size_t index, ElementMaterials& materials) {
    materials.assign(index, materials.part_of(optional_material_reference(node)));
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

// The parts of a generator's "materials" list, in its order; empty when it has none.
std::vector<std::uint32_t> generated_parts(const SceneNode& node, ElementMaterials& materials) {
    const auto list = node.optional_value("materials");
    if (!list) return {};
    if (!list->json().is_array() || list->json().items.empty())
        list->fail("expected a non-empty list of material names from \"materials\"");
    std::vector<std::uint32_t> parts;
    for (const SceneNode& name : list->elements()) parts.push_back(materials.part_of(material_reference(name)));
    return parts;
}

// "generate": {"count", "seed", "min": [x,y,z], "max": [x,y,z], "radius": [lo, hi], "weight": [lo, hi],
//              "half_size": [lo, hi], "materials": [names]} — elements uniformly placed in the box with uniform
// parameters, each with one of the materials (if given) chosen uniformly.
void generate_elements(const SceneNode& node, std::vector<Metacube>& elements, ElementMaterials& materials) {
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
    const std::vector<std::uint32_t> parts = generated_parts(node, materials);
    node.finish();
    // Where the generator or an element listed before it names a material, every element keeps its part.
    const bool keeps_parts = !parts.empty() || materials.keeps_parts();
    const std::uint64_t bytes_per_element = BlobGroup::kPeakBytesPerElement + (keeps_parts ? sizeof(std::uint32_t) : 0);
    node.charge_at("count", saturating_product({std::uint64_t(count), bytes_per_element}),
                   "a blob group of " + std::to_string(count) + " generated elements");
    const auto lerp = [](const std::array<double, 2>& r, double u) { return r[0] + (r[1] - r[0]) * u; };
    elements.reserve(elements.size() + std::size_t(count));
    if (keeps_parts) materials.reserve(elements.size() + std::size_t(count));
    for (int i = 0; i < count; ++i) {
        OrientedBox box;
        for (int k = 0; k < 3; ++k) box.centre[k] = lower[k] + (upper[k] - lower[k]) * uniform(seed, i, k);
        const double d = lerp(half_size, uniform(seed, i, 3));
        box.half_size = {d, d, d};
        if (!parts.empty())
            materials.assign(elements.size(),
                             parts[std::min(parts.size() - 1, std::size_t(uniform(seed, i, 6) * double(parts.size())))]);
        elements.push_back(make_element(node, box, lerp(radius, uniform(seed, i, 4)), lerp(weight, uniform(seed, i, 5))));
    }
}

std::unique_ptr<Shape> create(const SceneNode& node) {
    const std::vector<std::string> names(field_function_names().begin(), field_function_names().end());
    const std::string field = node.choice_or("field", "kim", names);
    const double sharpness = node.number_or("sharpness", 4.0, NumberRange::positive());
    const double threshold = node.number_or("threshold", 0.5, NumberRange::positive());
    std::vector<Metacube> elements;
    ElementMaterials materials;
    for (const SceneNode& element : node.object_array("elements"))
        elements.push_back(parse_element(element, elements.size(), materials));
    if (const auto generate = node.optional_object("generate")) generate_elements(*generate, elements, materials);
    if (elements.empty()) node.fail("a blob group needs \"elements\" or \"generate\"");
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const WorldBounds b = elements[i].support_bounds();
        if (std::max(max_component(abs(b.lower)), max_component(abs(b.upper))) > kWorldLimit)
            node.fail("element " + std::to_string(i) + " extends beyond 1e18 from the origin");
    }
    BlobMaterials parts = materials.finish(elements.size());
    return std::make_unique<BlobGroupShape>(BlobGroup(std::move(elements), make_field_function(field, sharpness), threshold),
                                            std::move(parts));
}

// The kernels' names come from FieldKernels (field_kernels.h).
std::string summary() {
    std::string kernels;
    for (std::string_view name : field_function_names()) kernels += (kernels.empty() ? "" : ", ") + std::string(name);
    return "blended metaballs/metacubes; field (" + kernels +
           "), threshold (0.5), sharpness (blinn), elements: [{center, radius, weight, half_size, rotate, material}], "
           "generate: {count, seed, min, max, radius, weight, half_size, materials}";
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "blobs", summary(), create)

}  // namespace isotrace
