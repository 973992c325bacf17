#include "geometry/polygonize/tessellated_shape.h"

#include "geometry/mesh/triangle_mesh_shape.h"
#include "geometry/polygonize/implicit_field_registry.h"
#include "geometry/polygonize/polygonize_field.h"

namespace isotrace {

std::unique_ptr<Shape> tessellated_shape(std::unique_ptr<Shape> shape, const SceneNode& settings) {
    PolygonizeOptions options;
    options.method = *polygonize_method_named(settings.choice_or("method", "dc", {"mc", "dc", "sdc"}));
    options.depth = settings.integer_or("depth", 6, NumberRange::between(min_depth(options.method), kMaxPolygonizeDepth));
    options.pole_cap = *pole_cap_named(settings.choice_or("pole_cap", "axis", {"axis", "normal", "vertical"}));
    if (settings.has("simplify")) options.simplify = settings.number("simplify", NumberRange::non_negative());
    if (settings.has("origin")) {
        const std::vector<double> o = settings.numbers("origin", 3);
        options.origin = Vec3d{o[0], o[1], o[2]};
    }
    settings.finish();
    std::unique_ptr<ImplicitField> field;
    try {
        field = implicit_field_of(*shape);
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

}  // namespace isotrace
