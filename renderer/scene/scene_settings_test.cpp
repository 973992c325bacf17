#include "renderer/scene/scene_settings.h"

#include <gtest/gtest.h>

#include "renderer/core/memory_budget.h"
#include "tests/support/input_error_of.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

const char* const kScene = R"({
  "film": {"spp": 16, "resolution": [64, 32]},
  "materials": {"gold": {"type": "principled", "roughness": 0.5}},
  "objects": [{"name": "dog", "material": "gold"}, {"name": "ball", "material": "gold"}, {"material": "gold"}]
})";

JsonValue with(const std::vector<std::string>& arguments) {
    JsonValue document = parse_json(kScene, "scene.json");
    std::vector<SceneSetting> settings;
    for (const std::string& argument : arguments) settings.push_back(parse_scene_setting(argument));
    apply_scene_settings(document, settings);
    return document;
}

InputError error_of(const std::vector<std::string>& arguments) {
    return testing::input_error_of([&] { with(arguments); }, "the settings");
}

TEST(SceneSettings, ParsesPathAndValue) {
    const SceneSetting setting = parse_scene_setting("objects.dog.material=\"a=b\"");
    EXPECT_EQ(setting.path, "objects.dog.material");
    EXPECT_EQ(setting.value, "\"a=b\"");
    EXPECT_EQ(setting.origin, "--set objects.dog.material=\"a=b\"");
    EXPECT_EQ(setting.path_column, 7);
    EXPECT_EQ(setting.value_column, 28);
    EXPECT_EQ(setting.text(), "objects.dog.material=\"a=b\"");
    EXPECT_THROW(parse_scene_setting("film.spp"), InputError);
}

TEST(SceneSettings, ReplacesValuesOfAnyKind) {
    const JsonValue document = with({"film.spp=256", "film.resolution=[8, 4]", "materials.gold.roughness=0.2",
                                     "objects.dog.material=\"silver\"", "objects.2.material={\"type\": \"diffuse\"}",
                                     "film.spp=true"});
    const JsonValue& film = *document.find("film");
    EXPECT_TRUE(film.find("spp")->is_bool());  // a later setting wins
    EXPECT_EQ(film.find("resolution")->items[1].number, 4);
    EXPECT_EQ(document.find("materials")->find("gold")->find("roughness")->number, 0.2);
    EXPECT_EQ(document.find("objects")->items[0].find("material")->string, "silver");
    EXPECT_TRUE(document.find("objects")->items[2].find("material")->is_object());
}

TEST(SceneSettings, ValuesAreLocatedInTheOption) {
    const JsonValue document = with({"film.resolution=[8, 4]"});
    const SourceLocation& where = document.find("film")->find("resolution")->items[1].location;
    EXPECT_EQ(where.file, "--set film.resolution=[8, 4]");
    EXPECT_EQ(where.line, 1);
    EXPECT_EQ(where.column, 27);
}

TEST(SceneSettings, BareWordsAreStrings) {
    const JsonValue document = with({"materials.gold.type=diffuse", "film.view=ACES 1.0 - SDR Video", "film.spp=1.2.3"});
    EXPECT_EQ(document.find("materials")->find("gold")->find("type")->string, "diffuse");
    EXPECT_EQ(document.find("film")->find("view")->string, "ACES 1.0 - SDR Video");
    const JsonValue& spp = *document.find("film")->find("spp");
    EXPECT_EQ(spp.string, "1.2.3");  // the loader then says that it is not a number
    EXPECT_EQ(spp.location.column, 16);
}

TEST(SceneSettings, TheLastKeyMayBeNew) {
    const JsonValue document = with({"film.view=sRGB", "film.sp=256", "camera={\"type\": \"perspective\"}"});
    EXPECT_EQ(document.find("film")->find("view")->string, "sRGB");
    EXPECT_EQ(document.find("film")->find("sp")->number, 256);
    EXPECT_EQ(document.find("camera")->find("type")->string, "perspective");
}

TEST(SceneSettings, MissingIntermediateKeysGetASuggestion) {
    const InputError error = error_of({"flim.spp=3"});
    EXPECT_EQ(std::string(error.what()),
              "--set flim.spp=3:1:7: no key \"flim\" in the scene (did you mean \"film\"?); keys there: film, "
              "materials, objects");
    const InputError deeper = error_of({"materials.glod.roughness=0.1"});
    EXPECT_EQ(deeper.location().column, 17);
    EXPECT_EQ(deeper.problem(), "no key \"glod\" in \"materials\" (did you mean \"gold\"?); keys there: gold");
}

TEST(SceneSettings, MissingSectionsWithoutACloseKeyAreCreated) {
    const JsonValue document = with({"integrator.type=preview", "film.filter.type=box"});
    EXPECT_EQ(document.find("integrator")->find("type")->string, "preview");
    EXPECT_EQ(document.find("integrator")->location.file, "--set integrator.type=preview");
    EXPECT_EQ(document.find("film")->find("filter")->find("type")->string, "box");
}

TEST(SceneSettings, ArrayElementsByIndexOrName) {
    EXPECT_EQ(error_of({"objects.3.material=x"}).problem(), "no element 3 in \"objects\", which has 3 element(s)");
    EXPECT_EQ(error_of({"objects.dgo.material=x"}).problem(),
              "no element of \"objects\" is named \"dgo\" (did you mean \"dog\"?); names: dog, ball (or use an index)");
    EXPECT_EQ(error_of({"film.spp.x=1"}).problem(), "\"film.spp\" is a number, which has no \"x\" in it");
    EXPECT_EQ(error_of({"objects.dog.material.x=1"}).problem(),
              "\"objects[0].material\" is a string, which has no \"x\" in it");
}

TEST(SceneSettings, ShortcutsCreateMissingSections) {
    JsonValue document = parse_json(kScene, "scene.json");
    apply_scene_settings(document, {seed_setting(7), shortcut_setting("film.view", "\"sRGB\"", "--view sRGB")});
    EXPECT_EQ(document.find("sampler")->find("seed")->number, 7);
    EXPECT_EQ(document.find("sampler")->find("seed")->location.file, "--seed 7");
    EXPECT_EQ(document.find("sampler")->find("seed")->location.line, 0);
    EXPECT_EQ(document.find("film")->find("view")->string, "sRGB");
}

TEST(SceneSettings, MalformedJsonValuesAreErrorsAtTheirPosition) {
    const InputError error = error_of({"film.resolution=[1, 2"});
    EXPECT_EQ(std::string(error.what()),
              "--set film.resolution=[1, 2:1:28: film.resolution: expected ',' or ']' but the value ended");
    EXPECT_EQ(error_of({"film.view={\"a\" 1}"}).location().column, 22);
}

TEST(SceneSettings, ValuesAreChargedToTheMemoryBudget) {
    std::string list = "film.resolution=[0";
    for (int i = 0; i < 20000; ++i) list += ", 0";
    JsonValue document = parse_json(kScene, "scene.json");
    MemoryBudget memory(std::uint64_t(1) << 20);
    try {
        apply_scene_settings(document, {parse_scene_setting(list + "]")}, &memory);
        ADD_FAILURE() << "a 20000-element value fitted in 1 MiB";
    } catch (const InputError& error) {
        EXPECT_NE(error.problem().find("the value of --set film.resolution=[0, 0"), std::string::npos) << error.what();
        EXPECT_EQ(error.field(), "film.resolution");
    }
}

TEST(SceneSettings, PathsAndValuesAreBounded) {
    EXPECT_NE(error_of({"film..spp=1"}).problem().find("empty key"), std::string::npos);
    EXPECT_EQ(error_of({"film..spp=1"}).location().column, 12);
    std::string deep = "film";
    for (int i = 0; i < 40; ++i) deep += ".a";
    EXPECT_NE(error_of({deep + "=1"}).problem().find("more than 32 keys"), std::string::npos);
    EXPECT_NE(error_of({std::string(2000, 'a') + "=1"}).problem().find("longer than 1024"), std::string::npos);
    EXPECT_NE(error_of({"film.view=\"" + std::string(70000, 'a') + "\""}).problem().find("longer than 65536"),
              std::string::npos);
}

}  // namespace
}  // namespace isotrace
