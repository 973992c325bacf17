// The showcase is what a new user sees first (tools/demo, the README's picture): it must show every surface family
// isotrace is for, path-traced with real materials, an environment light and depth of field.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "renderer/params/json_document.h"

namespace isotrace {
namespace {

struct Contents {
    std::set<std::string> shape_types;
    bool metaball = false, metacube = false, deformed_superquadric = false, deformed_mesh = false;
};

void collect_shape(const JsonValue& shape, Contents& contents) {
    const JsonValue* type = shape.find("type");
    ASSERT_TRUE(type && type->is_string());
    contents.shape_types.insert(type->string);
    if (type->string == "blobs")
        for (const JsonValue& element : shape.find("elements")->items) {
            const JsonValue* half_size = element.find("half_size");
            const bool cube = half_size && !(half_size->is_number() && half_size->number == 0);
            (cube ? contents.metacube : contents.metaball) = true;
        }
    if (type->string == "superquadric" && shape.find("deform")) contents.deformed_superquadric = true;
    if (type->string == "mesh" && shape.find("deformers")) contents.deformed_mesh = true;
    if (const JsonValue* children = shape.find("children"))
        for (const JsonValue& child : children->items) collect_shape(*child.find("shape"), contents);
}

TEST(ShowcaseScene, ShowsEverySurfaceFamilyPathTracedUnderASkyWithDepthOfField) {
    const JsonValue scene = parse_json_file(ISOTRACE_SCENES_DIR "/showcase.json");
    Contents contents;
    for (const JsonValue& object : scene.find("objects")->items) collect_shape(*object.find("shape"), contents);
    for (const char* type : {"blobs", "superquadric", "csg", "abm_patch", "mesh"})
        EXPECT_TRUE(contents.shape_types.count(type)) << "no " << type;
    EXPECT_TRUE(contents.metaball);
    EXPECT_TRUE(contents.metacube);
    EXPECT_TRUE(contents.deformed_superquadric);
    EXPECT_TRUE(contents.deformed_mesh);

    EXPECT_EQ(scene.find("integrator")->find("type")->string, "path");
    EXPECT_GT(scene.find("camera")->find("aperture_radius")->number, 0);
    bool environment = false;
    for (const JsonValue& light : scene.find("lights")->items)
        environment |= light.find("type")->string == "environment";
    EXPECT_TRUE(environment);
    bool glass = false, metal = false;
    for (const auto& [name, material] : scene.find("materials")->members) {
        glass |= material.find("transmission") != nullptr;
        metal |= material.find("metallic") != nullptr;
    }
    EXPECT_TRUE(glass);
    EXPECT_TRUE(metal);
}

}  // namespace
}  // namespace isotrace
