// The scene option "tessellate": {"method": "mc"|"dc"|"sdc", "depth": N, "origin": [x, y, z], "pole_cap": ...} on
// an object with an implicit shape replaces the shape by its polygonisation, traced by Embree as triangles, so a
// scene can show the tessellated surface beside the exact one.
#include "geometry/mesh/triangle_mesh_shape.h"
#include "geometry/polygonize/polygonize_field.h"
#include "renderer/params/scene_node.h"
#include "renderer/plugin/shape.h"

namespace isotrace {
namespace {

// Reads the settings from `settings` (the "tessellate" object); errors are reported there (a shape whose parts name
// materials, a shape without a field, a bad depth or origin, a surface with nothing to mesh).
std::unique_ptr<Shape> tessellated_shape(const SceneNode& settings, std::unique_ptr<Shape> shape) {
    if (!shape->part_materials().empty())
        settings.fail("a tessellated object shows one material, and this shape's parts name materials of their own "
                      "(remove \"tessellate\" or those materials)");
    PolygonizeOptions options;
    options.method = *polygonize_method_named(settings.choice_or("method", "dc", {"mc", "dc", "sdc"}));
    options.depth = settings.integer_or("depth", 6, NumberRange::between(min_depth(options.method), kMaxPolygonizeDepth));
    if (settings.has("pole_cap"))
        options.pole_cap = *pole_cap_named(settings.choice_or("pole_cap", "axis", {"axis", "normal", "vertical"}));
    if (settings.has("simplify")) options.simplify = settings.number("simplify", NumberRange::non_negative());
    if (settings.has("origin")) {
        const std::vector<double> o = settings.numbers("origin", 3);
        options.origin = Vec3d{o[0], o[1], o[2]};
    }
    settings.finish();
    std::unique_ptr<ImplicitField> field;
    try {
        field = shape->implicit_field();
    } catch (const std::invalid_argument& error) {
        settings.fail(error.what());
    }
    if (!field) settings.fail("a \"" + shape->type_name() + "\" shape is not an implicit surface");
    Polygonization result;
    try {
        result = polygonize_field(*field, options);
    } catch (const std::invalid_argument& error) {
        settings.fail(error.what());
    }
    if (result.mesh.triangles.empty()) settings.fail("the surface has no triangles at this depth");
    return std::make_unique<TriangleMeshShape>(std::move(result.mesh));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_wrapper_registry, "tessellate",
                         "an implicit object traced as its polygonisation; method, depth, origin, pole_cap, simplify",
                         tessellated_shape)

}  // namespace isotrace
