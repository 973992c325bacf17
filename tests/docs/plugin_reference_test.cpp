// Keeps the plugin reference complete: every registered plugin has a section in the README.md of the folder that
// registers it, and every parameter the plugin reads is named there. "Every parameter the plugin reads" is not
// guessed from the source: each plugin is loaded from probe scenes with one unknown key, and the loader's
// "known keys here" list (every key the plugin read or asked about) is what must be documented.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/mesh/mesh_deformer.h"
#include "renderer/core/input_error.h"
#include "renderer/plugin/camera.h"
#include "renderer/plugin/integrator.h"
#include "renderer/plugin/light.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/pixel_filter.h"
#include "renderer/plugin/sampler_registry.h"
#include "renderer/plugin/shape.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/support/scoped_environment_variable.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

namespace fs = std::filesystem;

const fs::path kSourceDir = ISOTRACE_SOURCE_DIR;
const std::string kProbeKey = "probe_unknown_key";

// Where a plugin of each registry sits in a scene: the text around the plugin's own JSON, and the JSON path of
// the plugin's node (the loader names it in its message).
struct Slot {
    std::string before, after, path;
};

const std::string kCamera = R"("camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}})";
const std::string kFilm = R"("film": {"resolution": [8, 8]})";
const std::string kMaterials = R"("materials": {"grey": {"type": "diffuse"}})";
const std::string kObjects = R"("objects": [{"material": "grey", "shape": {"type": "sphere"}}])";

const std::map<std::string, Slot>& slots() {
    static const std::map<std::string, Slot> table = {
        {"camera_registry", {"{\"isotrace\": 1, " + kFilm + ", \"camera\": ", ", " + kMaterials + ", " + kObjects + "}", "camera"}},
        {"sampler_registry", {"{\"isotrace\": 1, " + kFilm + ", " + kCamera + ", \"sampler\": ", "}", "sampler"}},
        {"pixel_filter_registry", {"{\"isotrace\": 1, " + kCamera + ", \"film\": {\"resolution\": [8, 8], \"filter\": ", "}}", "film.filter"}},
        {"integrator_registry", {"{\"isotrace\": 1, " + kFilm + ", " + kCamera + ", \"integrator\": ", "}", "integrator"}},
        {"material_registry", {"{\"isotrace\": 1, " + kFilm + ", " + kCamera + ", \"materials\": {\"m\": ", "}}", "materials.m"}},
        {"light_registry", {"{\"isotrace\": 1, " + kFilm + ", " + kCamera + ", \"lights\": [", "]}", "lights[0]"}},
        {"shape_registry", {"{\"isotrace\": 1, " + kFilm + ", " + kCamera + ", " + kMaterials +
                                ", \"objects\": [{\"material\": \"grey\", \"shape\": ",
                            "}]}", "objects[0].shape"}},
        {"shape_wrapper_registry", {"{\"isotrace\": 1, " + kFilm + ", " + kCamera + ", " + kMaterials +
                                        ", \"objects\": [{\"material\": \"grey\", \"shape\": {\"type\": \"sphere\"}, "
                                        "\"tessellate\": ",
                                    "}]}", "objects[0].tessellate"}},
        {"mesh_deformer_registry",
         {"{\"isotrace\": 1, " + kFilm + ", " + kCamera + ", " + kMaterials +
              ", \"objects\": [{\"material\": \"grey\", \"shape\": {\"type\": \"mesh\", "
              "\"positions\": [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [0, 2, 0]], "
              "\"triangles\": [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]], \"deformers\": [",
          "]}}]}", "objects[0].shape.deformers[0]"}},
    };
    return table;
}

// Probe nodes of each plugin: each holds the unknown key once, at the plugin's top level or in one of its nested
// objects. Together they reach every branch of the plugin's parsing (alternative forms of a parameter, optional
// nested objects), so that the union of the keys they report is everything the plugin reads. @SCENES@ is the
// source tree's scenes/ folder (for probes that need a file).
using PluginName = std::pair<std::string, std::string>;  // registry function, type

const std::map<PluginName, std::vector<std::string>>& probes() {
    static const std::map<PluginName, std::vector<std::string>> table = {
        {{"camera_registry", "perspective"},
         {R"({"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}, "probe_unknown_key": 0})",
          R"({"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0], "probe_unknown_key": 0}})",
          R"({"type": "perspective", "transform": {"translate": [0, 0, 5]}, "probe_unknown_key": 0})"}},
        {{"camera_registry", "orthographic"},
         {R"({"type": "orthographic", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}, "probe_unknown_key": 0})",
          R"({"type": "orthographic", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0], "probe_unknown_key": 0}})"}},
        {{"sampler_registry", "sobol"}, {R"({"type": "sobol", "probe_unknown_key": 0})"}},
        {{"sampler_registry", "independent"}, {R"({"type": "independent", "probe_unknown_key": 0})"}},
        {{"pixel_filter_registry", "box"}, {R"({"type": "box", "probe_unknown_key": 0})"}},
        {{"shape_registry", "box"}, {R"({"type": "box", "probe_unknown_key": 0})"}},
        {{"shape_registry", "plane"}, {R"({"type": "plane", "probe_unknown_key": 0})"}},
        {{"shape_registry", "disk"}, {R"({"type": "disk", "probe_unknown_key": 0})"}},
        {{"shape_registry", "rectangle"}, {R"({"type": "rectangle", "probe_unknown_key": 0})"}},
        {{"shape_wrapper_registry", "tessellate"}, {R"({"probe_unknown_key": 0})"}},
        {{"pixel_filter_registry", "gaussian"}, {R"({"type": "gaussian", "probe_unknown_key": 0})"}},
        {{"pixel_filter_registry", "blackman_harris"}, {R"({"type": "blackman_harris", "probe_unknown_key": 0})"}},
        {{"integrator_registry", "path"}, {R"({"type": "path", "probe_unknown_key": 0})"}},
        {{"integrator_registry", "direct"}, {R"({"type": "direct", "probe_unknown_key": 0})"}},
        {{"integrator_registry", "preview"}, {R"({"type": "preview", "probe_unknown_key": 0})"}},
        {{"integrator_registry", "aov"}, {R"({"type": "aov", "probe_unknown_key": 0})"}},
        {{"material_registry", "diffuse"}, {R"({"type": "diffuse", "probe_unknown_key": 0})"}},
        {{"material_registry", "conductor"},
         {R"({"type": "conductor", "metal": "Au", "probe_unknown_key": 0})",
          R"({"type": "conductor", "eta": [1, 1, 1], "k": [1, 1, 1], "probe_unknown_key": 0})"}},
        {{"material_registry", "dielectric"}, {R"({"type": "dielectric", "probe_unknown_key": 0})"}},
        {{"material_registry", "plastic"}, {R"({"type": "plastic", "probe_unknown_key": 0})"}},
        {{"material_registry", "principled"}, {R"({"type": "principled", "probe_unknown_key": 0})"}},
        {{"material_registry", "emissive"}, {R"({"type": "emissive", "radiance": 1, "probe_unknown_key": 0})"}},
        {{"light_registry", "point"}, {R"({"type": "point", "position": [0, 1, 0], "probe_unknown_key": 0})"}},
        {{"light_registry", "directional"}, {R"({"type": "directional", "direction": [0, -1, 0], "probe_unknown_key": 0})"}},
        {{"light_registry", "spot"},
         {R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "probe_unknown_key": 0})",
          R"({"type": "spot", "position": [0, 1, 0], "target": [0, 0, 0], "probe_unknown_key": 0})"}},
        {{"light_registry", "environment"},
         {R"({"type": "environment", "radiance": 1, "probe_unknown_key": 0})",
          R"({"type": "environment", "file": "@SCENES@/data/sky.exr", "probe_unknown_key": 0})"}},
        {{"shape_registry", "cone"}, {R"({"type": "cone", "probe_unknown_key": 0})"}},
        {{"shape_registry", "cylinder"}, {R"({"type": "cylinder", "probe_unknown_key": 0})"}},
        {{"shape_registry", "torus"}, {R"({"type": "torus", "probe_unknown_key": 0})"}},
        {{"shape_registry", "sphere"},
         {R"({"type": "sphere", "probe_unknown_key": 0})",
          R"({"type": "sphere", "spheres": [{"radius": 1, "probe_unknown_key": 0}]})"}},
        {{"shape_registry", "mesh"},
         {R"({"type": "mesh", "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]], "probe_unknown_key": 0})",
          R"({"type": "mesh", "file": "@SCENES@/data/teapot.bpt", "probe_unknown_key": 0})"}},
        {{"shape_registry", "blobs"},
         {R"({"type": "blobs", "elements": [{"center": [0, 0, 0], "radius": 1}], "probe_unknown_key": 0})",
          R"({"type": "blobs", "elements": [{"center": [0, 0, 0], "radius": 1, "probe_unknown_key": 0}]})",
          R"({"type": "blobs", "generate": {"count": 2, "min": [0, 0, 0], "max": [1, 1, 1], "probe_unknown_key": 0}})"}},
        {{"shape_registry", "isosurface"},
         {R"({"type": "isosurface", "function": "length(p) - 1", "contained_by": {"sphere": {"radius": 2}}, "probe_unknown_key": 0})",
          R"({"type": "isosurface", "function": "length(p) - 1", "contained_by": {"box": {"min": [-2, -2, -2], "max": [2, 2, 2], "probe_unknown_key": 0}}})",
          R"({"type": "isosurface", "function": "length(p) - 1", "contained_by": {"sphere": {"radius": 2, "probe_unknown_key": 0}}})"}},
        {{"shape_registry", "superquadric"},
         {R"({"type": "superquadric", "probe_unknown_key": 0})",
          R"({"type": "superquadric", "superquadrics": [{"probe_unknown_key": 0}]})",
          R"({"type": "superquadric", "deform": [{"probe_unknown_key": 0}]})",
          R"({"type": "superquadric", "deform": [{"bend": {"curvature": 0.1, "probe_unknown_key": 0}}]})"}},
        {{"shape_registry", "csg"},
         {R"({"type": "csg", "op": "union", "children": [{"shape": {"type": "sphere"}}], "probe_unknown_key": 0})",
          R"({"type": "csg", "op": "union", "children": [{"shape": {"type": "sphere"}, "probe_unknown_key": 0}]})"}},
        {{"shape_registry", "abm_patch"},
         {R"({"type": "abm_patch", "boundary": [{"points": [[0, 0, 0], [1, 0, 0]]}, {"points": [[1, 0, 0], [0, 1, 0]]},
              {"points": [[0, 1, 0], [0, 0, 0]]}], "probe_unknown_key": 0})",
          R"({"type": "abm_patch", "draw": "curves", "boundary": [{"points": [[0, 0, 0], [1, 0, 0]]},
              {"points": [[1, 0, 0], [0, 1, 0]]}, {"points": [[0, 1, 0], [0, 0, 0]]}], "probe_unknown_key": 0})",
          R"({"type": "abm_patch", "patches": [{"boundary": [{"points": [[0, 0, 0], [1, 0, 0]]},
              {"points": [[1, 0, 0], [0, 1, 0]]}, {"points": [[0, 1, 0], [0, 0, 0]]}], "probe_unknown_key": 0}]})",
          R"({"type": "abm_patch", "boundary": [{"type": "nurbs", "points": [[0, 0, 0], [1, 0, 0]], "weights": [1, 1], "probe_unknown_key": 0},
              {"points": [[1, 0, 0], [0, 1, 0]]}, {"points": [[0, 1, 0], [0, 0, 0]]}]})",
          R"({"type": "abm_patch", "curves": {"a": {"points": [[0, 0, 0], [1, 0, 0]]}}, "boundary": [
              {"curve": "a", "reversed": false, "probe_unknown_key": 0}, {"points": [[1, 0, 0], [0, 1, 0]]},
              {"points": [[0, 1, 0], [0, 0, 0]]}]})"}},
        {{"shape_registry", "sweep_tubes"},
         {R"({"type": "sweep_tubes", "deformers": [{"type": "sweep", "key_sections": [
              {"center": [0, 0, 0], "radius": 1}, {"center": [0, 0, 1], "radius": 1}]}], "probe_unknown_key": 0})"}},
        {{"mesh_deformer_registry", "sweep"},
         {R"({"type": "sweep", "key_sections": [{"center": [0, 0, 0], "radius": 1}, {"center": [0, 1, 0], "radius": 1}],
              "probe_unknown_key": 0})",
          R"({"type": "sweep", "key_sections": [{"center": [0, 0, 0], "radius": 1, "probe_unknown_key": 0},
              {"center": [0, 1, 0], "radius": 1}]})",
          R"({"type": "sweep", "key_sections": [{"center": [0, 0, 0], "radius": 1}, {"center": [0, 1, 0], "radius": 1}],
              "edits": [{"key": 1, "probe_unknown_key": 0}]})"}},
        {{"mesh_deformer_registry", "sweep_hierarchy"},
         {R"({"type": "sweep_hierarchy", "sweeps": [{"name": "a", "key_sections": [{"center": [0, 0, 0], "radius": 1},
              {"center": [0, 1, 0], "radius": 1}]}], "probe_unknown_key": 0})",
          R"({"type": "sweep_hierarchy", "sweeps": [{"name": "a", "key_sections": [{"center": [0, 0, 0], "radius": 1},
              {"center": [0, 1, 0], "radius": 1}]}, {"name": "b", "parent": "a", "key_sections": [
              {"center": [0, 0.5, 0], "radius": 0.2}, {"center": [0.5, 0.5, 0], "radius": 0.2}], "probe_unknown_key": 0}]})",
          R"({"type": "sweep_hierarchy", "sweeps": [{"name": "a", "key_sections": [{"center": [0, 0, 0], "radius": 1},
              {"center": [0, 1, 0], "radius": 1}]}], "edits": [{"sweep": "a", "key": 1, "probe_unknown_key": 0}]})"}},
    };
    return table;
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

// A registration in the source tree: which registry, which folder.
struct Registration {
    std::string registry, type;
    fs::path folder;
    bool test_only = false;  // registered by a *_test.cpp (a test double, not a user-facing plugin)
};

std::vector<Registration> registrations_in_source() {
    const std::regex registration(R"re(ISOTRACE_REGISTER_PLUGIN\(\s*(\w+)\s*,\s*"([^"]+)")re");
    std::vector<Registration> found;
    for (const char* top : {"renderer", "geometry", "integrators"})
        for (const auto& entry : fs::recursive_directory_iterator(kSourceDir / top)) {
            if (entry.path().extension() != ".cpp") continue;
            const std::string text = read_text(entry.path());
            const bool test = entry.path().stem().string().ends_with("_test");
            for (std::sregex_iterator it(text.begin(), text.end(), registration), end; it != end; ++it)
                if ((*it)[1] != "registry_function")  // the macro's own definition
                    found.push_back({(*it)[1], (*it)[2], entry.path().parent_path(), test});
        }
    return found;
}

std::vector<Registration> user_plugins() {
    std::vector<Registration> plugins;
    for (const Registration& r : registrations_in_source())
        if (!r.test_only) plugins.push_back(r);
    return plugins;
}

// Every type registered at run time, per registry function name, with its summary.
std::map<std::string, std::map<std::string, std::string>> registered_at_run_time() {
    std::map<std::string, std::map<std::string, std::string>> all;
    const auto collect = [&](const std::string& name, const auto& registry) {
        for (const auto& [type, entry] : registry.entries()) all[name][type] = entry.summary;
    };
    collect("camera_registry", camera_registry());
    collect("sampler_registry", sampler_registry());
    collect("pixel_filter_registry", pixel_filter_registry());
    collect("integrator_registry", integrator_registry());
    collect("material_registry", material_registry());
    collect("light_registry", light_registry());
    collect("shape_registry", shape_registry());
    collect("shape_wrapper_registry", shape_wrapper_registry());
    collect("mesh_deformer_registry", mesh_deformer_registry());
    return all;
}

// The keys a plugin reported in its probes; `top_level` only those of its own node (not of nested objects).
struct ProbedKeys {
    std::set<std::string> all, top_level;
};

ProbedKeys probe_keys(const Registration& plugin) {
    ProbedKeys keys;
    const Slot& slot = slots().at(plugin.registry);
    const testing::TemporaryDirectory directory("plugin_probe");
    for (const std::string& probe : probes().at({plugin.registry, plugin.type})) {
        const std::string text =
            slot.before + replace_all(probe, "@SCENES@", (kSourceDir / "scenes").generic_string()) + slot.after;
        const std::string path = directory.write("probe.json", text).string();
        try {
            load_scene(path);
            ADD_FAILURE() << plugin.type << ": the probe loaded without complaint:\n" << text;
            continue;
        } catch (const InputError& error) {
            const std::string problem = error.problem();
            const std::string known = "; known keys here: ";
            const auto at = problem.find(known);
            if (problem.find("unknown key \"" + kProbeKey + "\"") != 0 || at == std::string::npos) {
                ADD_FAILURE() << plugin.type << ": the probe failed for another reason: " << error.what() << "\n" << text;
                continue;
            }
            std::stringstream list(problem.substr(at + known.size()));
            const bool top = error.field() == slot.path + "." + kProbeKey;
            for (std::string key; std::getline(list, key, ',');) {
                key.erase(0, key.find_first_not_of(' '));
                if (key == "type") continue;
                keys.all.insert(key);
                if (top) keys.top_level.insert(key);
            }
        }
    }
    return keys;
}

// The section of `markdown` whose heading contains `text` (a plugin's section names it in backticks): up to the
// next heading of the same or a higher level. Empty when there is none.
std::string section_naming(const std::string& markdown, const std::string& text) {
    std::istringstream lines(markdown);
    std::string section;
    int level = 0;
    bool in_code = false;
    for (std::string line; std::getline(lines, line);) {
        if (line.starts_with("```")) in_code = !in_code;
        const std::size_t hashes = in_code ? 0 : line.find_first_not_of('#');
        const bool heading = hashes > 0 && hashes != std::string::npos && hashes <= 6 && line[hashes] == ' ';
        if (heading && level > 0 && int(hashes) <= level) break;
        if (heading && level == 0 && line.find(text) != std::string::npos) level = int(hashes);
        if (level > 0) section += line + "\n";
    }
    return section;
}

class PluginReference : public ::testing::Test {
protected:
    ScopedEnvironmentVariable no_ocio_{"OCIO", std::nullopt};  // the shipped config, whatever the environment says
};

TEST_F(PluginReference, SourceRegistrationsAreTheRegisteredPlugins) {
    const auto run_time = registered_at_run_time();
    std::set<std::pair<std::string, std::string>> in_source, test_doubles;
    for (const Registration& r : registrations_in_source()) (r.test_only ? test_doubles : in_source).insert({r.registry, r.type});
    EXPECT_GE(in_source.size(), 31u);
    for (const auto& [registry, type] : in_source)
        EXPECT_TRUE(run_time.count(registry) && run_time.at(registry).count(type))
            << registry << " \"" << type << "\" is in the source but not registered (or its registry is not probed here)";
    for (const auto& [registry, types] : run_time)
        for (const auto& [type, summary] : types)
            EXPECT_TRUE(in_source.count({registry, type}) || test_doubles.count({registry, type}))
                << registry << " \"" << type << "\" is registered, but no ISOTRACE_REGISTER_PLUGIN line names it";
}

TEST_F(PluginReference, EveryPluginHasProbes) {
    for (const Registration& plugin : user_plugins()) {
        EXPECT_TRUE(slots().count(plugin.registry)) << plugin.registry << ": no slot for its plugins in the probe scenes";
        EXPECT_TRUE(probes().count({plugin.registry, plugin.type})) << "\"" << plugin.type << "\": add probes for it to this test";
    }
}

TEST_F(PluginReference, EveryPluginHasASectionInItsFolderReadme) {
    for (const Registration& plugin : user_plugins()) {
        const fs::path readme = plugin.folder / "README.md";
        ASSERT_TRUE(fs::exists(readme)) << "\"" << plugin.type << "\" is registered in " << plugin.folder.string()
                                        << ", which has no README.md";
        EXPECT_FALSE(section_naming(read_text(readme), "`" + plugin.type + "`").empty())
            << readme.string() << " has no heading naming `" << plugin.type << "`";
    }
}

TEST_F(PluginReference, EveryParameterIsDocumentedInThePluginsSection) {
    for (const Registration& plugin : user_plugins()) {
        if (!probes().count({plugin.registry, plugin.type}) || !slots().count(plugin.registry)) continue;  // reported above
        const fs::path readme = plugin.folder / "README.md";
        const std::string section = section_naming(read_text(readme), "`" + plugin.type + "`");
        const ProbedKeys keys = probe_keys(plugin);
        EXPECT_FALSE(keys.all.empty()) << plugin.type << ": the probes reported no keys";
        for (const std::string& key : keys.all)
            EXPECT_NE(section.find("`" + key + "`"), std::string::npos)
                << readme.string() << ", section `" << plugin.type << "`: parameter `" << key << "` is not documented";
    }
}

TEST_F(PluginReference, RegistrationSummariesNameEveryTopLevelParameter) {
    const auto run_time = registered_at_run_time();
    for (const Registration& plugin : user_plugins()) {
        if (!probes().count({plugin.registry, plugin.type}) || !slots().count(plugin.registry)) continue;
        const std::string& summary = run_time.at(plugin.registry).at(plugin.type);
        for (const std::string& key : probe_keys(plugin).top_level)
            EXPECT_TRUE(std::regex_search(summary, std::regex("(^|[^a-z_])" + key + "([^a-z_]|$)")))
                << plugin.type << ": `isotrace info --plugins` does not name its parameter " << key << " (summary: \""
                << summary << "\")";
    }
}

TEST_F(PluginReference, ThePluginIndexLinksEveryPlugin) {
    const std::string index = section_naming(read_text(kSourceDir / "docs" / "scene-format.md"), "# Plugin index");
    ASSERT_FALSE(index.empty()) << "docs/scene-format.md has no \"Plugin index\" section";
    for (const Registration& plugin : user_plugins()) {
        const std::string folder = fs::relative(plugin.folder, kSourceDir).generic_string();
        const std::regex row("\\| `" + plugin.type + "` \\| \\[[^\\]]*\\]\\(\\.\\./" + folder + "/README\\.md#");
        EXPECT_TRUE(std::regex_search(index, row))
            << "docs/scene-format.md's plugin index has no row for `" << plugin.type << "` linking " << folder << "/README.md";
    }
}

// The section finder itself: a heading of a deeper level stays in the section, one of the same level ends it.
TEST(PluginReferenceSection, EndsAtTheNextHeadingOfTheSameLevel) {
    const std::string text = "# A\n## `x`\nabout x\n### detail\nmore\n```\n# not a heading\n```\n## `y`\nabout y\n";
    EXPECT_EQ(section_naming(text, "`x`"), "## `x`\nabout x\n### detail\nmore\n```\n# not a heading\n```\n");
    EXPECT_EQ(section_naming(text, "`y`"), "## `y`\nabout y\n");
    EXPECT_EQ(section_naming(text, "`z`"), "");
}

}  // namespace
}  // namespace isotrace
