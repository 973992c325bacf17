#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <set>

#include "renderer/film/aov.h"
#include "renderer/plugin/shape.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/scoped_environment_variable.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

// A camera line, a material and one sphere: the smallest complete scene. Tests splice their changes in.
const std::string kCamera =
    R"(  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},)";

std::string minimal_scene(const std::string& extra_top_level = "") {
    return "{\n"
           "  \"isotrace\": 1,\n" +
           kCamera + "\n" + extra_top_level +
           "  \"materials\": {\"grey\": {\"type\": \"diffuse\"}},\n"
           "  \"objects\": [{\"material\": \"grey\", \"shape\": {\"type\": \"sphere\", \"radius\": 1}}]\n"
           "}\n";
}

std::string joined(const std::vector<std::string>& names) {
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    return list;
}

class LoadScene : public ::testing::Test {
protected:
    // The shipped OCIO config, whatever $OCIO says in the environment running the tests.
    ScopedEnvironmentVariable no_ocio_{"OCIO", std::nullopt};
    testing::TemporaryDirectory dir_{"loader"};

    std::string write(const std::string& text, const std::string& name = "scene.json") {
        return dir_.write(name, text).string();
    }

    std::unique_ptr<LoadedScene> load(const std::string& text, const SceneOverrides& overrides = {}) {
        return load_scene(write(text), overrides);
    }

    // Loads `text`, which must fail, and checks position, JSON path and the complete message.
    void expect_error(const std::string& text, int line, int column, const std::string& field,
                      const std::string& problem, const SceneOverrides& overrides = {}) {
        const std::string path = write(text);
        std::string prefix = path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
        if (!field.empty()) prefix += field + ": ";
        testing::expect_input_error([&] { load_scene(path, overrides); }, path, line, column, field, prefix + problem);
    }
};

TEST_F(LoadScene, MinimalSceneUsesTheDefaults) {
    const auto loaded = load(minimal_scene());
    EXPECT_EQ(loaded->film.raster.width, 640);
    EXPECT_EQ(loaded->film.raster.height, 480);
    EXPECT_EQ(loaded->film.crop.x0, 0);
    EXPECT_EQ(loaded->film.crop.y0, 0);
    EXPECT_EQ(loaded->film.crop.x1, 640);
    EXPECT_EQ(loaded->film.crop.y1, 480);
    EXPECT_TRUE(loaded->film.aovs.empty());
    EXPECT_FALSE(loaded->film.half_float);
    EXPECT_EQ(loaded->spp, 16);
    EXPECT_EQ(loaded->seed, 0u);
    EXPECT_EQ(loaded->camera_type, "perspective");
    EXPECT_EQ(loaded->filter_type, "gaussian");
    EXPECT_EQ(loaded->sampler_type, "sobol");
    EXPECT_EQ(loaded->integrator_type, "path");
    EXPECT_EQ(loaded->description, "");
    EXPECT_EQ(loaded->display, "");
    EXPECT_EQ(loaded->view, "");
    ASSERT_NE(loaded->colours, nullptr);
    EXPECT_EQ(loaded->colours->working_space(), "ACEScg");
    ASSERT_NE(loaded->camera, nullptr);
    ASSERT_NE(loaded->filter, nullptr);
    ASSERT_NE(loaded->sampler, nullptr);
    ASSERT_NE(loaded->integrator, nullptr);
    ASSERT_NE(loaded->scene, nullptr);

    ASSERT_EQ(loaded->scene->objects().size(), 1u);
    const SceneObject& sphere = loaded->scene->objects()[0];
    EXPECT_EQ(sphere.name, "objects[0]");
    EXPECT_EQ(sphere.material, loaded->scene->find_material("grey"));
    EXPECT_NE(sphere.material, nullptr);
    EXPECT_EQ(loaded->scene->material_names(), std::vector<std::string>{"grey"});
    // Committed: Embree knows the sphere's bounds.
    EXPECT_EQ(loaded->scene->build_statistics().objects, 1u);
    const Bounds3f bounds = loaded->scene->bounds();
    EXPECT_NEAR(bounds.lower.x, -1.0f, 1e-4f);
    EXPECT_NEAR(bounds.upper.y, 1.0f, 1e-4f);
}

TEST_F(LoadScene, SceneSettingsReplaceTheDefaults) {
    const auto loaded = load(minimal_scene(
        "  \"description\": \"a test\",\n"
        "  \"colour\": {\"working_space\": \"lin_rec709\"},\n"
        "  \"film\": {\"resolution\": [320, 200], \"spp\": 64, \"exr_pixel\": \"half\", \"aovs\": [\"depth\", \"all\"],\n"
        "           \"filter\": {\"type\": \"box\", \"radius\": 0.5}},\n"
        "  \"sampler\": {\"type\": \"independent\", \"seed\": 9},\n"
        "  \"integrator\": {\"type\": \"preview\", \"ambient\": 0.5},\n"));
    EXPECT_EQ(loaded->description, "a test");
    EXPECT_EQ(loaded->colours->working_space(), "Linear Rec.709 (sRGB)");
    EXPECT_EQ(loaded->film.raster.width, 320);
    EXPECT_EQ(loaded->film.raster.height, 200);
    EXPECT_EQ(loaded->film.crop.x1, 320);
    EXPECT_EQ(loaded->film.crop.y1, 200);
    EXPECT_EQ(loaded->spp, 64);
    EXPECT_TRUE(loaded->film.half_float);
    EXPECT_EQ(loaded->filter_type, "box");
    EXPECT_EQ(loaded->sampler_type, "independent");
    EXPECT_EQ(loaded->seed, 9u);
    // "depth" first, then every other AOV once, in table order.
    ASSERT_EQ(loaded->film.aovs.size(), all_aovs().size());
    EXPECT_EQ(loaded->film.aovs[0], Aov::Depth);
    EXPECT_EQ(loaded->film.aovs[1], Aov::Albedo);
    EXPECT_EQ(std::set<Aov>(loaded->film.aovs.begin(), loaded->film.aovs.end()).size(), all_aovs().size());
}

TEST_F(LoadScene, CommandLineOverridesWin) {
    SceneOverrides overrides;
    overrides.settings.push_back(spp_setting(4));
    overrides.settings.push_back(resolution_setting(RasterSize{32, 16}));
    overrides.settings.push_back(seed_setting(7));
    overrides.extra_aovs = {Aov::Albedo, Aov::Depth};
    const auto loaded = load(minimal_scene("  \"film\": {\"resolution\": [320, 200], \"spp\": 64, \"aovs\": [\"depth\", "
                                           "\"normal\"]},\n  \"sampler\": {\"seed\": 3},\n"),
                             overrides);
    EXPECT_EQ(loaded->spp, 4);
    EXPECT_EQ(loaded->film.raster.width, 32);
    EXPECT_EQ(loaded->film.raster.height, 16);
    EXPECT_EQ(loaded->film.crop.x1, 32);  // the crop follows the overridden raster
    EXPECT_EQ(loaded->film.crop.y1, 16);
    EXPECT_EQ(loaded->seed, 7u);
    // The scene's AOVs, then the extra ones not already present.
    EXPECT_EQ(loaded->film.aovs, (std::vector<Aov>{Aov::Depth, Aov::Normal, Aov::Albedo}));
}

TEST_F(LoadScene, ShortcutsCreateTheSectionsTheySet) {
    SceneOverrides overrides;
    overrides.settings = {spp_setting(4), seed_setting(18446744073709551615ull)};
    const auto loaded = load(minimal_scene(), overrides);  // no "film", no "sampler"
    EXPECT_EQ(loaded->spp, 4);
    EXPECT_EQ(loaded->seed, 18446744073709551615ull);
    EXPECT_TRUE(loaded->settings.empty());  // recorded apart
}

TEST_F(LoadScene, OverridesAreValidatedLikeTheFile) {
    SceneOverrides overrides;
    overrides.settings.push_back(spp_setting(0));
    testing::expect_input_error([&] { load_scene(write(minimal_scene()), overrides); }, "--spp 0", 0, 0, "film.spp",
                                "--spp 0: film.spp: value 0 out of range: must be in [1, 16777216]");
    overrides.settings = {parse_scene_setting("film.spp=abc")};
    testing::expect_input_error([&] { load_scene(write(minimal_scene("  \"film\": {},\n")), overrides); },
                                "--set film.spp=abc", 1, 16, "film.spp",
                                "--set film.spp=abc:1:16: film.spp: expected a number, found string");
    // A new last key is checked like any key of the file: an unknown one is named at the override.
    overrides.settings = {parse_scene_setting("film.sp=256")};
    testing::expect_input_error([&] { load_scene(write(minimal_scene("  \"film\": {},\n")), overrides); },
                                "--set film.sp=256", 1, 15, "film.sp",
                                "--set film.sp=256:1:15: film.sp: unknown key \"sp\" (did you mean \"spp\"?); known keys "
                                "here: aovs, crop, display, exr_pixel, filter, resolution, spp, view");
}

TEST_F(LoadScene, OverridesAreListedInOrder) {
    SceneOverrides overrides;
    overrides.settings = {parse_scene_setting("camera.fov=30"), spp_setting(2), parse_scene_setting("objects.0.material=\"grey\"")};
    const auto loaded = load(minimal_scene(), overrides);
    EXPECT_EQ(loaded->settings, (std::vector<std::string>{"camera.fov=30", "objects.0.material=\"grey\""}));
    EXPECT_EQ(loaded->spp, 2);
}

TEST_F(LoadScene, IncludedFilesMergeAndResolveTheirOwnPaths) {
    dir_.write("lib/meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    dir_.write("lib/objects.json", "{ // objects of the library\n"
                                   "  \"objects\": [{\"name\": \"tri\", \"material\": \"grey\",\n"
                                   "               \"shape\": {\"type\": \"mesh\", \"file\": \"meshes/tri.obj\"}},],\n"
                                   "}\n");
    const std::string scene = minimal_scene("  \"include\": \"lib/objects.json\",\n");
    const auto loaded = load(scene);
    ASSERT_EQ(loaded->scene->objects().size(), 2u);
    EXPECT_EQ(loaded->scene->objects()[0].name, "tri");  // included arrays come first
    const std::vector<std::filesystem::path> expected{std::filesystem::absolute(dir_ / "lib/meshes/tri.obj"),
                                                      std::filesystem::absolute(dir_ / "lib/objects.json")};
    EXPECT_EQ(loaded->referenced_files, expected);
}

TEST_F(LoadScene, ErrorsInIncludedFilesNameThem) {
    const std::string library = dir_.write("lib.json", "{\n  \"materials\": {\"red\": {\"type\": \"diffuse\",\n"
                                                       "    \"reflectanse\": 0.5}}\n}\n").string();
    const std::string scene = minimal_scene("  \"include\": [\"lib.json\"],\n");
    testing::expect_input_error([&] { load(scene); }, library, 3, 20, "materials.red.reflectanse",
                                library + ":3:20: materials.red.reflectanse: unknown key \"reflectanse\" (did you mean "
                                          "\"reflectance\"?); known keys here: emission, reflectance, two_sided_emission, type");
}

TEST_F(LoadScene, CropWindowBecomesPixelBounds) {
    const auto loaded = load(minimal_scene("  \"film\": {\"resolution\": [100, 50], \"crop\": [0.1, 0.55, 0.25, 1]},\n"));
    EXPECT_EQ(loaded->film.crop.x0, 10);
    EXPECT_EQ(loaded->film.crop.x1, 55);
    EXPECT_EQ(loaded->film.crop.y0, 13);  // ceil(12.5): pixel 12's centre (12.5) lies on the boundary
    EXPECT_EQ(loaded->film.crop.y1, 50);
    // A sliver still covers one pixel; a crop at the far edge keeps the last pixel.
    const auto sliver = load(minimal_scene("  \"film\": {\"resolution\": [100, 50], \"crop\": [0.5, 0.5001, 0.999, 1]},\n"));
    EXPECT_EQ(sliver->film.crop.x0, 50);
    EXPECT_EQ(sliver->film.crop.x1, 51);
    EXPECT_EQ(sliver->film.crop.y0, 49);
    EXPECT_EQ(sliver->film.crop.y1, 50);
}

TEST_F(LoadScene, CropErrors) {
    expect_error(minimal_scene("  \"film\": {\"crop\": [0.6, 0.4, 0, 1]},\n"), 4, 20, "film.crop",
                 "expected [x_min, x_max, y_min, y_max] with min < max");
    expect_error(minimal_scene("  \"film\": {\"crop\": [0, 1.5, 0, 1]},\n"), 4, 24, "film.crop[1]",
                 "value 1.5 out of range: must be in [0, 1]");
}

TEST_F(LoadScene, UnknownTopLevelKey) {
    expect_error(minimal_scene("  \"lights_\": [],\n"), 4, 14, "lights_",
                 "unknown key \"lights_\" (did you mean \"lights\"?); known keys here: camera, colour, definitions, description, "
                 "film, include, integrator, isotrace, lights, materials, objects, sampler, values");
}

TEST_F(LoadScene, NamedValuesAreSubstitutedAndOverridable) {
    const std::string scene = minimal_scene("  \"values\": {\"fov\": 30, \"spp\": 8},\n"
                                            "  \"film\": {\"spp\": {\"$value\": \"spp\"}, \"resolution\": [8, 8]},\n");
    EXPECT_EQ(load(scene)->spp, 8);
    SceneOverrides overrides;
    overrides.settings = {parse_scene_setting("values.spp=3")};
    EXPECT_EQ(load(scene, overrides)->spp, 3);
    // A value out of range for the field that uses it is reported where it is written, with the field's path.
    overrides.settings = {parse_scene_setting("values.spp=0")};
    testing::expect_input_error([&] { load_scene(write(scene), overrides); }, "--set values.spp=0", 1, 18, "film.spp",
                                "--set values.spp=0:1:18: film.spp: value 0 out of range: must be in [1, 16777216]");
}

TEST_F(LoadScene, UnknownMaterialName) {
    const std::string text =
        "{\n"
        "  \"isotrace\": 1,\n" +
        kCamera +
        "\n"
        "  \"materials\": {\"grey\": {\"type\": \"diffuse\"}, \"red\": {\"type\": \"diffuse\", \"reflectance\": [1, 0, 0]}},\n"
        "  \"objects\": [\n"
        "    {\"material\": \"grey\", \"shape\": {\"type\": \"sphere\"}},\n"
        "    {\"material\": \"gery\", \"shape\": {\"type\": \"sphere\"}}\n"
        "  ]\n"
        "}\n";
    expect_error(text, 7, 18, "objects[1].material", "unknown material \"gery\" (did you mean \"grey\"?); defined: grey, red");
}

TEST_F(LoadScene, InlineMaterialsAreNotListedAsNames) {
    const std::string text =
        "{\n"
        "  \"isotrace\": 1,\n" +
        kCamera +
        "\n"
        "  \"objects\": [\n"
        "    {\"material\": {\"type\": \"emissive\", \"radiance\": 2}, \"shape\": {\"type\": \"sphere\"}},\n"
        "    {\"material\": \"lamp\", \"shape\": {\"type\": \"sphere\"}}\n"
        "  ]\n"
        "}\n";
    expect_error(text, 6, 18, "objects[1].material", "unknown material \"lamp\"; the scene defines no materials");
}

TEST_F(LoadScene, MissingCamera) {
    expect_error(
        "{\n"
        "  \"isotrace\": 1,\n"
        "  \"objects\": []\n"
        "}\n",
        1, 1, "", "missing required field \"camera\"");
}

TEST_F(LoadScene, NegativeRadius) {
    const std::string text =
        "{\n"
        "  \"isotrace\": 1,\n" +
        kCamera +
        "\n"
        "  \"materials\": {\"grey\": {\"type\": \"diffuse\"}},\n"
        "  \"objects\": [\n"
        "    {\"material\": \"grey\",\n"
        "     \"shape\": {\"type\": \"sphere\", \"radius\": -2}}\n"
        "  ]\n"
        "}\n";
    expect_error(text, 7, 44, "objects[0].shape.radius", "value -2 out of range: must be > 0");
}

TEST_F(LoadScene, ZeroResolution) {
    expect_error(minimal_scene("  \"film\": {\"resolution\": [0, 480]},\n"), 4, 27, "film.resolution[0]",
                 "value 0 out of range: must be in [1, 65536]");
    expect_error(minimal_scene("  \"film\": {\"resolution\": [64.5, 480]},\n"), 4, 26, "film.resolution",
                 "expected whole pixel counts");
}

TEST_F(LoadScene, WrongFormatVersion) {
    expect_error("{\n  \"isotrace\": 2,\n" + kCamera + "\n  \"objects\": []\n}\n", 2, 15, "isotrace",
                 "unsupported scene format version 2 (this build reads 1)");
    expect_error("{\n" + kCamera + "\n  \"objects\": []\n}\n", 1, 1, "", "missing required field \"isotrace\"");
    expect_error("[1, 2]", 1, 1, "", "a scene file must contain a JSON object");
}

TEST_F(LoadScene, UnknownShapeType) {
    const std::string text =
        "{\n"
        "  \"isotrace\": 1,\n" +
        kCamera +
        "\n"
        "  \"materials\": {\"grey\": {\"type\": \"diffuse\"}},\n"
        "  \"objects\": [{\"material\": \"grey\", \"shape\": {\"type\": \"spehre\"}}]\n"
        "}\n";
    expect_error(text, 5, 54, "objects[0].shape.type",
                 "unknown shape type \"spehre\" (did you mean \"sphere\"?); available: " +
                     joined(shape_registry().types()));
}

TEST_F(LoadScene, UnknownAovIsReportedAtItsEntry) {
    std::vector<std::string> names;
    for (const AovInfo& info : all_aovs()) names.push_back(info.name);
    expect_error(minimal_scene("  \"film\": {\"aovs\": [\"albedo\", \"normals\"]},\n"), 4, 31, "film.aovs[1]",
                 "unknown AOV \"normals\" (did you mean \"normal\"?); available: " + joined(names) + ", all");
}

TEST_F(LoadScene, UnknownWorkingSpaceIsReportedOnce) {
    expect_error(minimal_scene("  \"colour\": {\"working_space\": \"ACEScgg\"},\n"), 4, 31, "colour.working_space",
                 "unknown colour space \"ACEScgg\" (did you mean \"ACEScg\"?)");
}

TEST_F(LoadScene, MissingFileNamesTheFile) {
    const std::string path = (dir_ / "absent.json").string();
    testing::expect_input_error([&] { load_scene(path); }, path, 0, 0, "",
                                path + ": file not found");
}

TEST_F(LoadScene, ShippedCornellBox) {
    const auto loaded = load_scene(ISOTRACE_SCENES_DIR "/cornell_box.json");
    EXPECT_EQ(loaded->film.raster.width, 512);
    EXPECT_EQ(loaded->film.raster.height, 512);
    EXPECT_EQ(loaded->spp, 64);
    EXPECT_EQ(loaded->camera_type, "perspective");
    EXPECT_EQ(loaded->integrator_type, "path");
    EXPECT_EQ(loaded->scene->material_names(), (std::vector<std::string>{"green", "light", "red", "white"}));
    ASSERT_EQ(loaded->scene->objects().size(), 8u);
    EXPECT_EQ(loaded->scene->objects()[0].name, "floor");
    EXPECT_EQ(loaded->scene->objects()[7].name, "light");
    EXPECT_EQ(loaded->scene->objects()[7].material, loaded->scene->find_material("light"));
    EXPECT_EQ(loaded->scene->objects()[3].material, loaded->scene->find_material("green"));
    // The only light is the ceiling lamp, an area light made from the emissive quad.
    EXPECT_EQ(loaded->scene->lights().size(), 1u);
    EXPECT_EQ(loaded->scene->objects()[7].area_light.light, loaded->scene->lights()[0].get());
    EXPECT_EQ(loaded->scene->build_statistics().area_lights, 1u);
    // Committed, and the millimetre measurements were scaled to metres.
    const BuildStatistics& statistics = loaded->scene->build_statistics();
    EXPECT_EQ(statistics.objects, 8u);
    EXPECT_EQ(statistics.primitives_by_type.at(loaded->scene->objects()[0].shape->type_name()),
              std::size_t(5 * 2 + 2 * 10 + 2));
    const Bounds3f bounds = loaded->scene->bounds();
    EXPECT_NEAR(bounds.lower.x, 0.0f, 1e-4f);
    EXPECT_NEAR(bounds.lower.y, 0.0f, 1e-4f);
    EXPECT_NEAR(bounds.lower.z, 0.0f, 1e-4f);
    EXPECT_NEAR(bounds.upper.x, 0.556f, 1e-4f);
    EXPECT_NEAR(bounds.upper.y, 0.5488f, 1e-4f);
    EXPECT_NEAR(bounds.upper.z, 0.5592f, 1e-4f);
}

// Two equal metaballs, one red and one blue: the blend on the plane half way between them.
std::string two_coloured_metaballs(const std::string& blue_material) {
    return "{\n"
           "  \"isotrace\": 1,\n" +
           kCamera +
           "\n"
           "  \"materials\": {\"red\": {\"type\": \"diffuse\", \"reflectance\": [0.9, 0.1, 0.05]},\n"
           "                \"blue\": " + blue_material + "},\n"
           "  \"objects\": [{\"material\": \"red\", \"shape\": {\"type\": \"blobs\", \"elements\": [\n"
           "    {\"center\": [-0.6, 0, 0], \"radius\": 1},\n"
           "    {\"center\": [0.6, 0, 0], \"radius\": 1, \"material\": \"blue\"}]}}]\n"
           "}\n";
}

TEST_F(LoadScene, MaterialsOfTwoEqualMetaballsBlendHalfWayOnTheMidPlane) {
    const auto loaded = load(two_coloured_metaballs(
        R"({"type": "principled", "base_colour": [0.05, 0.2, 0.8], "roughness": 0.3, "metallic": 1})"));
    const RenderScene& scene = *loaded->scene;
    const Material* red = scene.find_material("red");
    const Material* blue = scene.find_material("blue");
    for (const float y : {0.0f, 0.05f, -0.07f}) {  // the neck's radius is 0.1
        const std::optional<SurfaceHit> hit = scene.intersect(Ray{{0, y, 5}, {0, 0, -1}}, RayKind::Camera);
        ASSERT_TRUE(hit);
        ASSERT_EQ(hit->blend.count, 2);
        EXPECT_EQ(hit->blend.weight[0], 0.5f);
        EXPECT_EQ(hit->blend.weight[1], 0.5f);
        const PrincipledParameters r = red->principled_parameters(*hit), b = blue->principled_parameters(*hit);
        const PrincipledParameters mixed = hit->material->principled_parameters(*hit);
        EXPECT_EQ(mixed.base_colour, (r.base_colour + b.base_colour) * 0.5f);
        EXPECT_EQ(mixed.metallic, 0.5f);
        EXPECT_EQ(mixed.specular, 0.5f);  // diffuse has none, principled the default 1
        EXPECT_EQ(hit->material->albedo(*hit), (red->albedo(*hit) + blue->albedo(*hit)) * 0.5f);
    }
    // Towards a centre, that element's material takes over.
    const std::optional<SurfaceHit> near_blue = scene.intersect(Ray{{0.9f, 0, 5}, {0, 0, -1}}, RayKind::Camera);
    ASSERT_TRUE(near_blue);
    EXPECT_GT(near_blue->material->principled_parameters(*near_blue).metallic, 0.9f);
}

TEST_F(LoadScene, MaterialsThatCannotBlendAreRefusedWhereTheyAreNamed) {
    const std::string text = two_coloured_metaballs(R"({"type": "conductor", "metal": "Au"})");
    expect_error(text, 8, 54, "objects[0].shape.elements[1].material",
                 "materials that blend across a surface must be \"principled\" or \"diffuse\"");
}

TEST_F(LoadScene, UvMappedTexturesNeedSurfacesWithUv) {
    const std::string text = two_coloured_metaballs(
        R"({"type": "principled", "base_colour": {"type": "checker", "projection": "uv"}})");
    expect_error(text, 5, 97, "materials.blue.base_colour.projection",
                 "this texture is mapped by uv, but the shape of object \"objects[0]\" (blobs) has no uv: use a \"solid\", \"planar\", \"triplanar\", "
                 "\"spherical\" or \"cylindrical\" projection");
}

TEST_F(LoadScene, TessellatingAShapeWhosePartsNameMaterialsIsRefused) {
    // The triangles show one material: element materials (and CSG children's) used to be dropped silently.
    std::string text = two_coloured_metaballs(R"({"type": "diffuse"})");
    const std::string shape = "\"shape\": {\"type\": \"blobs\"";
    text.replace(text.find(shape), shape.size(), "\"tessellate\": {\"depth\": 4}, " + shape);
    expect_error(text, 6, 49, "objects[0].tessellate",
                 "a tessellated object shows one material, and this shape's parts name materials of their own "
                 "(remove \"tessellate\" or those materials)");
}

}  // namespace
}  // namespace isotrace
