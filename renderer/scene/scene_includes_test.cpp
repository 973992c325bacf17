#include "renderer/scene/scene_includes.h"

#include <gtest/gtest.h>

#include "renderer/core/memory_budget.h"
#include "tests/support/input_error_of.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

class SceneIncludes : public ::testing::Test {
protected:
    testing::TemporaryDirectory dir_{"includes"};

    std::string write(const std::string& name, const std::string& text) { return dir_.write(name, text).string(); }
    SceneDocument read(const std::string& path, std::uint64_t max_bytes = kDefaultMaxJsonFileBytes) {
        return read_scene_document(path, max_bytes, nullptr);
    }
    InputError read_error(const std::string& path, std::uint64_t max_bytes = kDefaultMaxJsonFileBytes) {
        return testing::input_error_of([&] { read(path, max_bytes); }, "reading " + path);
    }
};

TEST(MergeJson, ObjectsMergeKeyByKeyTopLevelArraysConcatenateOverlayWins) {
    JsonValue base = parse_json(R"({"a": {"x": 1, "y": 2, "v": [1, 2, 3]}, "list": [1, 2], "n": 1, "kind": [1]})",
                                "base.json");
    merge_scene_sections(base, parse_json(R"({"a": {"y": 3, "z": 4, "v": [5]}, "list": [3], "n": "two",
                                              "kind": {"k": 1}, "new": 5})",
                                          "overlay.json"));
    const JsonValue* a = base.find("a");
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->find("x")->number, 1);
    EXPECT_EQ(a->find("y")->number, 3);
    EXPECT_EQ(a->find("y")->location.file, "overlay.json");
    EXPECT_EQ(a->find("z")->number, 4);
    ASSERT_EQ(a->find("v")->items.size(), 1u);  // an array inside a section is a value: replaced
    ASSERT_EQ(base.find("list")->items.size(), 3u);
    EXPECT_EQ(base.find("list")->items[2].number, 3);
    EXPECT_EQ(base.find("list")->items[0].location.file, "base.json");
    EXPECT_EQ(base.find("n")->string, "two");
    EXPECT_TRUE(base.find("kind")->is_object());
    EXPECT_EQ(base.find("new")->number, 5);
}

TEST(MergeJson, LargeObjectsStayIndexed) {
    std::string base_text = "{", overlay_text = "{";
    for (int i = 0; i < 40; ++i) base_text += (i ? ", " : "") + std::string("\"k") + std::to_string(i) + "\": " + std::to_string(i);
    for (int i = 30; i < 60; ++i) overlay_text += (i > 30 ? ", " : "") + std::string("\"k") + std::to_string(i) + "\": -1";
    JsonValue base = parse_json(base_text + "}", "a.json");
    merge_scene_sections(base, parse_json(overlay_text + "}", "b.json"));
    ASSERT_EQ(base.members.size(), 60u);
    ASSERT_TRUE(base.key_index);
    EXPECT_EQ(base.key_index->size(), 60u);
    EXPECT_EQ(base.find("k5")->number, 5);
    EXPECT_EQ(base.find("k35")->number, -1);
    EXPECT_EQ(base.find("k59")->number, -1);
}

TEST_F(SceneIncludes, OwnValuesWinLaterIncludesWinArraysInIncludeOrder) {
    write("lib/a.json", R"({"film": {"spp": 1, "resolution": [8, 8]}, "lights": [{"name": "a"}]})");
    write("lib/b.json", R"({"film": {"spp": 2}, "lights": [{"name": "b"}], "include": "c.json"})");
    write("lib/c.json", R"({"film": {"exr_pixel": "half"}, "lights": [{"name": "c"}]})");
    const std::string scene = write("scene.json", R"({"include": ["lib/a.json", "lib/b.json"], "film": {"resolution": [4, 4]},
        "lights": [{"name": "own"}]})");
    const SceneDocument document = read(scene);
    const JsonValue& root = document.root;
    EXPECT_EQ(root.find("include"), nullptr);
    const JsonValue& film = *root.find("film");
    EXPECT_EQ(film.find("spp")->number, 2);
    EXPECT_EQ(film.find("resolution")->items[0].number, 4);
    EXPECT_EQ(film.find("exr_pixel")->string, "half");
    std::vector<std::string> lights;
    for (const JsonValue& light : root.find("lights")->items) lights.push_back(light.find("name")->string);
    EXPECT_EQ(lights, (std::vector<std::string>{"a", "c", "b", "own"}));  // b's own include comes before b's own
    // Every value keeps its file and position.
    EXPECT_EQ(film.find("spp")->location.file, dir_.path() / "lib/b.json");
    EXPECT_EQ(film.find("exr_pixel")->location.file, dir_.path() / "lib/c.json");
    EXPECT_EQ(film.find("exr_pixel")->location.column, 24);
    EXPECT_EQ(root.location.file, scene);
    EXPECT_EQ(document.included_files.size(), 3u);
    EXPECT_EQ(document.included_directories.at((dir_.path() / "lib/c.json").string()), dir_.path() / "lib");
}

TEST_F(SceneIncludes, CyclesNameTheChain) {
    write("a.json", "{\"include\": \"b.json\"}");
    write("b.json", "{\n  \"include\": [\"a.json\"]\n}");
    const std::string scene = write("scene.json", "{\"include\": \"a.json\"}");
    const InputError error = read_error(scene);
    const std::string dir = dir_.path().string() + "/";
    EXPECT_EQ(error.location().file, dir + "b.json");
    EXPECT_EQ(error.location().line, 2);
    EXPECT_EQ(error.location().column, 15);
    EXPECT_EQ(error.problem(), "cannot include \"a.json\": include cycle: " + dir + "scene.json -> " + dir + "a.json -> " +
                                   dir + "b.json -> " + dir + "a.json");
    write("self.json", "{\"include\": \"self.json\"}");
    EXPECT_NE(std::string(read_error(dir + "self.json").what()).find("include cycle"), std::string::npos);
}

TEST_F(SceneIncludes, DepthAndCountAreBounded) {
    for (int i = 0; i <= kMaxIncludeDepth + 1; ++i)
        write("d" + std::to_string(i) + ".json", "{\"include\": \"d" + std::to_string(i + 1) + ".json\"}");
    write("d" + std::to_string(kMaxIncludeDepth + 2) + ".json", "{}");
    EXPECT_NE(read_error(dir_.path() / "d0.json").problem().find("includes nest more than 16 deep"), std::string::npos);
    EXPECT_NO_THROW(read(dir_.path() / ("d2.json")));  // 16 levels below it
    std::string many = "{\"include\": [";
    for (int i = 0; i <= kMaxIncludedFiles; ++i) many += std::string(i ? ", " : "") + "\"empty.json\"";
    write("empty.json", "{}");
    EXPECT_NE(read_error(write("many.json", many + "]}")).problem().find("more than 256 files"), std::string::npos);
}

TEST_F(SceneIncludes, BadIncludesAreReportedAtTheIncludeString) {
    const std::string dir = dir_.path().string() + "/";
    write("ok.json", "{}");
    write("array.json", "[1, 2]");
    write("broken.json", "{\n  \"a\": tru\n}");
    const auto expect_refused = [&](const std::string& include, const std::string& problem) {
        const InputError error = read_error(write("scene.json", "{\n  \"include\": [\"ok.json\", " + include + "]\n}"));
        EXPECT_EQ(error.location().file, dir + "scene.json") << error.what();
        EXPECT_EQ(error.location().line, 2) << error.what();
        EXPECT_EQ(error.location().column, 26) << error.what();
        EXPECT_EQ(error.field(), "include");
        EXPECT_EQ(error.problem(), problem);
    };
    expect_refused("\"missing.json\"", "cannot include \"missing.json\": " + dir + "missing.json: file not found");
    expect_refused("\"broken.json\"",
                   "cannot include \"broken.json\": " + dir + "broken.json:2:8: expected a JSON value but found 't'");
    expect_refused("\".\"", "cannot include \".\": " + dir + ".: is a directory, not a regular file (isotrace reads only regular files)");
    const InputError not_object = read_error(write("scene.json", "{\"include\": \"array.json\"}"));
    EXPECT_EQ(not_object.problem(), "cannot include \"array.json\": expected an object of scene sections, found array");
    const InputError not_name = read_error(write("scene.json", "{\"include\": [\"array.json\", 3]}"));
    EXPECT_EQ(not_name.problem(), "expected a file name or a list of file names");
    EXPECT_EQ(not_name.location().column, 13);
}

TEST_F(SceneIncludes, IncludedBytesCountAgainstTheSceneSizeLimit) {
    write("big.json", "{\"description\": \"" + std::string(2000, 'x') + "\"}");
    const std::string scene = write("scene.json", "{\"include\": \"big.json\"}");
    EXPECT_NO_THROW(read(scene, 4096));
    const InputError error = read_error(scene, 1024);
    EXPECT_NE(error.problem().find("larger than the limit"), std::string::npos) << error.what();
    EXPECT_NE(error.problem().find("left for the files the scene includes"), std::string::npos) << error.what();
}

}  // namespace
}  // namespace isotrace
