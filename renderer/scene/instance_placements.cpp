#include "renderer/scene/instance_placements.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "renderer/params/transform_parser.h"
#include "renderer/params/world_limit.h"
#include "renderer/sampling/hash.h"
#include "renderer/scene/object_builder.h"

namespace isotrace {
namespace {

// Placement i's k-th random number in [0, 1): a hash, so a placement's draw depends on the seed and its index alone.
double grid_random(std::uint64_t seed, std::size_t placement, int k) {
    return double(hash_combine(seed, std::uint64_t(placement), k) >> 11) * 0x1p-53;
}

// node[key] as [low, high] with low <= high, or one number for both; `fallback` when absent.
std::array<double, 2> range_or(const SceneNode& node, const std::string& key, std::array<double, 2> fallback,
                               NumberRange allowed) {
    if (!node.has(key)) return fallback;
    if (node.optional_value(key)->json().is_number()) {
        const double value = node.number(key, allowed);
        return {value, value};
    }
    const std::vector<double> range = node.numbers(key, 2, allowed);
    if (range[0] > range[1]) node.fail_at(key, "expected [low, high] with low <= high");
    return {range[0], range[1]};
}

// What one placed object keeps: its record, its share of Embree's BVH over the placements (measured: 24 bytes for
// many placements, 120 for a few, RenderScene::kPlacementsBuiltCompactly) and, while the scene is read, its Placement.
constexpr std::uint64_t kBytesPerPlacedObject = sizeof(PlacementRecord) + sizeof(Placement) + 128;

// Fails at node[field] when `placements` placements of `parts` objects each are too many or do not fit in memory.
void charge_placements(const SceneNode& node, const std::string& field, std::uint64_t placements, std::uint64_t parts) {
    const std::uint64_t objects = saturating_product({placements, parts});
    if (objects > kMaxPlacedObjects)
        node.fail_at(field, "these placements add " + std::to_string(objects) + " objects (" + std::to_string(placements) +
                                " placements of " + std::to_string(parts) + " parts); at most " +
                                std::to_string(kMaxPlacedObjects) + " are allowed");
    node.charge_at(field, saturating_product({objects, kBytesPerPlacedObject}),
                   std::to_string(objects) + " placed objects");
}

void read_grid(const SceneNode& grid, const std::string& name, const Transform& outer, const Material* outer_material,
               std::size_t parts, RenderScene& scene, std::vector<Placement>& placements) {
    const std::vector<double> counts = grid.numbers("counts", 3, NumberRange::between(1, double(kMaxPlacementsPerObject)));
    for (double count : counts)
        if (count != std::floor(count)) grid.fail_at("counts", "expected whole numbers of placements along x, y and z");
    const double total = counts[0] * counts[1] * counts[2];
    if (total > double(kMaxPlacementsPerObject))
        grid.fail_at("counts", "a grid places at most " + std::to_string(kMaxPlacementsPerObject) + " copies (asked: " +
                                   std::to_string(std::uint64_t(total)) + ")");
    const std::vector<double> spacing = grid.numbers("spacing", 3, world_length(true));
    const double jitter = grid.number_or("jitter", 0, NumberRange::unit_interval());
    Vec3d axis(0, 1, 0);
    std::array<double, 2> angles{0, 0};
    if (auto rotate = grid.optional_object("rotate")) {
        if (rotate->has("axis")) axis = unit_direction(*rotate, "axis");
        angles = range_or(*rotate, "angle", {0, 0}, NumberRange::between(-36000, 36000));
        rotate->finish();
    }
    const std::array<double, 2> scales = range_or(grid, "scale", {1, 1}, NumberRange::between(1e-6, 1e6));
    std::vector<const Material*> materials;
    if (auto list = grid.optional_value("materials")) {
        if (!list->json().is_array() || list->json().items.empty()) list->fail("expected a non-empty list of materials");
        for (const SceneNode& item : list->elements()) materials.push_back(material_of_value(item, scene));
    }
    const std::uint64_t seed = grid.unsigned_or("seed", 0);
    grid.finish();
    charge_placements(grid, "counts", std::uint64_t(total), parts);

    const std::size_t nx = std::size_t(counts[0]), ny = std::size_t(counts[1]), nz = std::size_t(counts[2]);
    placements.reserve(nx * ny * nz);
    for (std::size_t iz = 0; iz < nz; ++iz)
        for (std::size_t iy = 0; iy < ny; ++iy)
            for (std::size_t ix = 0; ix < nx; ++ix) {
                const std::size_t i = placements.size();
                const auto cell = [&](std::size_t index, std::size_t count, int axis_index) {
                    const double offset = jitter * (grid_random(seed, i, axis_index) - 0.5);
                    return (double(index) - 0.5 * double(count - 1) + offset) * spacing[std::size_t(axis_index)];
                };
                const Vec3d position(cell(ix, nx, 0), cell(iy, ny, 1), cell(iz, nz, 2));
                const double angle = angles[0] + (angles[1] - angles[0]) * grid_random(seed, i, 3);
                const double scale = scales[0] + (scales[1] - scales[0]) * grid_random(seed, i, 4);
                const Material* material =
                    materials.empty() ? outer_material
                                      : materials[std::min(materials.size() - 1,
                                                           std::size_t(grid_random(seed, i, 5) * double(materials.size())))];
                placements.push_back({name + "[" + std::to_string(i) + "]",
                                      outer * Transform::translate(position) * Transform::rotate(axis, angle) *
                                          Transform::scale({scale, scale, scale}),
                                      material});
            }
}

}  // namespace

std::vector<Placement> read_placements(const SceneNode& node, const std::string& name, std::size_t parts,
                                       RenderScene& scene) {
    const Transform outer = parse_optional_transform(node, "transform");
    const auto material_value = node.optional_value("material");
    const Material* outer_material = material_value ? material_of_value(*material_value, scene) : nullptr;
    if (node.has("placements") && node.has("grid"))
        node.fail_at("grid", "an object places its copies by \"placements\" or by a \"grid\", not both");
    std::vector<Placement> placements;
    if (auto grid = node.optional_object("grid")) {
        read_grid(*grid, name, outer, outer_material, parts, scene, placements);
    } else if (node.has("placements")) {
        const std::vector<SceneNode> items = node.object_array("placements");
        if (items.size() > kMaxPlacementsPerObject)
            node.fail_at("placements", "an object places at most " + std::to_string(kMaxPlacementsPerObject) + " copies");
        charge_placements(node, "placements", items.size(), parts);
        for (std::size_t i = 0; i < items.size(); ++i) {
            const SceneNode& item = items[i];
            const auto own_material = item.optional_value("material");
            placements.push_back({item.string_or("name", name + "[" + std::to_string(i) + "]"),
                                  outer * parse_optional_transform(item, "transform"),
                                  own_material ? material_of_value(*own_material, scene) : outer_material, i});
            item.finish();
        }
    } else {
        charge_placements(node, "instance", 1, parts);
        placements.push_back({name, outer, outer_material});
    }
    return placements;
}

void fail_at_placement(const SceneNode& node, const Placement& placement, const std::string& problem) {
    if (placement.entry != Placement::kNoEntry)
        node.object_array("placements").at(placement.entry).fail_at("transform", problem);
    node.fail_at(node.has("grid") ? "grid" : "transform", problem);
}

}  // namespace isotrace
