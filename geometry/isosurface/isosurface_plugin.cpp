// Scene plugin "isosurface": the zero set of a function written in the expression language (docs/expressions.md)
// within a box or ball container, whose terms may be the fields of other shapes ("fields": named shapes).
#include <algorithm>
#include <memory>
#include <stdexcept>

#include "geometry/expression/expression_field.h"
#include "geometry/isosurface/derived_container.h"
#include "geometry/isosurface/isosurface_shape.h"
#include "renderer/core/did_you_mean.h"
#include "renderer/params/world_limit.h"

namespace isotrace {
namespace {

// Isosurfaces nest as field terms of isosurfaces (a term is a shape that may have terms of its own): each level
// compiles and octrees its own function, so the nesting is bounded.
constexpr int kMaxFieldNesting = 4;

int field_nesting(const SceneNode& node) {
    int levels = 0;
    for (std::size_t at = node.path().find(".fields."); at != std::string::npos; at = node.path().find(".fields.", at + 1))
        ++levels;
    return levels;
}

constexpr const char* kContainerSyntax =
    "\"contained_by\": {\"box\": {\"min\": [x, y, z], \"max\": [x, y, z]}} or {\"sphere\": {\"center\": [x, y, z], "
    "\"radius\": r}}, a finite region that holds its surface";

// The container written in the scene, or nothing when there is none.
std::optional<Container> parse_container(const SceneNode& node) {
    if (!node.has("contained_by")) return std::nullopt;
    const SceneNode container = node.object("contained_by");
    if (container.keys().size() != 1 || !(container.has("box") || container.has("sphere"))) {
        container.finish();  // names an unknown key, with a suggestion
        container.fail("give one of \"box\" or \"sphere\"");
    }
    if (container.has("box")) {
        const SceneNode box = container.object("box");
        const Vec3d lower = world_point(box, "min"), upper = world_point(box, "max");
        for (int k = 0; k < 3; ++k)
            if (!(lower[k] < upper[k])) box.fail_at("max", "must exceed \"min\" on every axis (the box would hold nothing)");
        box.finish();
        return Container::box(lower, upper);
    }
    const SceneNode sphere = container.object("sphere");
    const Vec3d centre = sphere.has("center") ? world_point(sphere, "center") : Vec3d{};
    const double radius = sphere.number("radius", world_length());
    if (!within_world(centre + Vec3d{radius, radius, radius}) || !within_world(centre - Vec3d{radius, radius, radius}))
        sphere.fail_at("radius", beyond_world_problem("the sphere"));
    sphere.finish();
    return Container::sphere(centre, radius);
}

// A cube about the origin proven to hold the surface, for a function given without a container.
Container derived_container(const SceneNode& node, const ExpressionSource& source, const ExpressionNames& names) {
    // Other shapes' fields are not required to bound their values over unbounded boxes.
    if (!names.fields.empty())
        node.fail(std::string("an isosurface with field terms needs ") + kContainerSyntax);
    if (const std::optional<Container> derived = derive_container(*compile_expression(source, names))) return *derived;
    node.fail("interval evaluation cannot prove that the function is positive outside a cube of half-size up to 2^" +
              std::to_string(kLargestDerivedHalfSize) + " m about the origin (its surface may be unbounded): give it " +
              kContainerSyntax);
}

// The shapes of "fields", each one's field under its name; `used` are the names the function calls.
std::vector<std::unique_ptr<Shape>> parse_fields(const SceneNode& node, const std::vector<std::string>& used,
                                                 ExpressionNames& names) {
    std::vector<std::unique_ptr<Shape>> shapes;
    const std::optional<SceneNode> fields = node.optional_object("fields");
    if (!fields) return shapes;
    if (field_nesting(*fields) + 1 > kMaxFieldNesting)
        node.fail_at("fields", "field terms nest more than " + std::to_string(kMaxFieldNesting) +
                                   " isosurfaces deep");
    for (const std::string& name : fields->keys()) {
        if (std::find(used.begin(), used.end(), name) == used.end())
            fields->fail_at(name, "the function does not use the field \"" + name + "\"" + did_you_mean(name, used));
        const SceneNode entry = fields->object(name);
        std::unique_ptr<Shape> shape = shape_registry().create(entry);
        std::unique_ptr<ImplicitField> field;
        try {
            field = shape->implicit_field();
        } catch (const std::invalid_argument& error) {
            entry.fail(error.what());
        }
        if (!field) entry.fail_at("type", "a \"" + shape->type_name() + "\" has no field to use as a term");
        names.fields[name] = std::shared_ptr<const ImplicitField>(std::move(field));
        shapes.push_back(std::move(shape));
    }
    return shapes;
}

std::unique_ptr<Shape> create(const SceneNode& node) {
    const std::optional<Container> given = parse_container(node);
    const ExpressionSource source = expression_source(node, "function");
    const std::vector<std::string> used = expression_field_terms(source);
    ExpressionNames names;
    names.parameters = expression_parameters(node, "parameters");
    std::vector<std::unique_ptr<Shape>> shapes = parse_fields(node, used, names);
    const Container container = given ? *given : derived_container(node, source, names);

    IsosurfaceSettings settings;
    settings.resolution = node.number_or("resolution", 0, world_length(true));
    settings.max_work = std::uint64_t(node.integer_or("max_work", int(settings.max_work), NumberRange::between(64, 1e9)));
    settings.octree.max_depth = node.integer_or("octree_depth", settings.octree.max_depth, NumberRange::between(0, 10));
    settings.octree.max_cells =
        std::size_t(node.integer_or("max_cells", int(settings.octree.max_cells), NumberRange::between(1, 1 << 24)));

    const IntervalBox& box = container.bounds();
    std::shared_ptr<const ExpressionField> field = compile_expression(source, names, {box.lower(), box.upper()});
    std::vector<IntervalBox> cells =
        surface_cells(*field, container, settings.octree, *node.context().memory, node.location());
    if (cells.empty() && !given)
        node.fail("the function has no surface (interval evaluation proves it positive everywhere)");
    if (cells.empty())
        node.fail_at("contained_by", "the function has no surface inside the container (interval evaluation "
                                     "proves it positive throughout)");
    node.context().memory->charge(cells.size() * sizeof(LinearCellBound), "isosurface cell bounds", node.location());
    CellFields cell_fields = pruned_cell_fields(field, cells, *node.context().memory, node.location());
    return std::make_unique<IsosurfaceShape>(std::move(field), container, std::move(cells), settings,
                                             std::move(cell_fields), std::move(shapes));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "isosurface",
                         "the zero set of function (docs/expressions.md) with parameters and fields (other shapes as "
                         "terms), inside contained_by {box} or {sphere} (derived when interval arithmetic can bound "
                         "it); resolution, max_work, octree_depth, max_cells",
                         create)

}  // namespace isotrace
