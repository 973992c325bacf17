// The "csg" scene type: {"op": "union" | "intersection" | "difference", "children": [{"shape": {...},
// "material": "name", "transform": ...}, ...]}. Children are any shapes that are closed solids, CSG included.
#include "geometry/csg/csg_shape.h"
#include "geometry/csg/material_reference_parser.h"
#include "renderer/params/transform_parser.h"

namespace isotrace {
namespace {

CsgOperation parse_operation(const SceneNode& node) {
    if (!node.has("op")) node.fail("missing required field \"op\" (union, intersection or difference)");
    const std::string op = node.choice_or("op", "", {"union", "intersection", "difference"});
    if (op == "union") return CsgOperation::Union;
    if (op == "intersection") return CsgOperation::Intersection;
    return CsgOperation::Difference;
}

CsgChild parse_child(const SceneNode& child) {
    CsgChild result;
    result.shape = shape_registry().create(child.object("shape"));
    const auto* solid = dynamic_cast<const Solid*>(result.shape.get());
    if (!solid) child.fail("CSG needs a closed solid; " + result.shape->type_name() + " is not a solid");
    if (const std::string problem = solid->solid_problem(); !problem.empty())
        child.fail("CSG needs a closed solid; " + problem);
    result.to_csg = parse_optional_transform(child, "transform");
    result.material = optional_material_reference(child);
    child.finish();
    return result;
}

std::unique_ptr<Shape> create(const SceneNode& node) {
    const CsgOperation operation = parse_operation(node);
    if (!node.has("children")) node.fail("missing required field \"children\" (the solids to combine)");
    const std::vector<SceneNode> items = node.object_array("children");
    if (items.empty()) node.fail_at("children", "a CSG needs at least one child");
    std::vector<CsgChild> children;
    for (const SceneNode& item : items) children.push_back(parse_child(item));
    return std::make_unique<CsgShape>(operation, std::move(children));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "csg",
                         "constructive solid geometry; op (union, intersection, difference), children: [{shape, "
                         "material, transform}]",
                         create)

}  // namespace isotrace
