#include <algorithm>
#include <chrono>
#include <deque>
#include <cmath>
#include <cstdio>

#include "renderer/params/transform_parser.h"
#include "renderer/params/world_limit.h"
#include "renderer/plugin/light.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/sampler_registry.h"
#include "renderer/plugin/shape.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/scene/named_values.h"
#include "renderer/scene/object_builder.h"
#include "renderer/scene/scene_definitions.h"
#include "renderer/scene/scene_includes.h"

namespace isotrace {
namespace {

constexpr int kSceneFormatVersion = 1;
constexpr int kMaxResolution = 1 << 16;
constexpr float kMaxLightPower = 1e30f;

// Stand-ins for optional sections the file leaves out, so their plugins read defaults through the same
// code. Each sits at its parent's position, so an error about a default names a real place in the file.
class DefaultSections {
public:
    // parent[key] if present, else an empty object located at `parent`.
    SceneNode object_or_defaults(const SceneNode& parent, const std::string& key) {
        if (auto child = parent.optional_object(key)) return *child;
        JsonValue& stand_in = stand_ins_.emplace_back();
        stand_in.kind = JsonValue::Kind::Object;
        stand_in.location = parent.json().location;
        return SceneNode(stand_in, parent.child_path(key), parent.shared_context());
    }

private:
    std::deque<JsonValue> stand_ins_;  // deque: references stay valid as it grows
};

// First pixel at or after `fraction` of `size` pixels. A product within rounding error of a whole number is
// that number: 100 * 0.55 is 55.000000000000007 in doubles, and must give 55, not 56.
int pixel_edge(int size, double fraction) {
    const double x = size * fraction;
    const double nearest = std::round(x);
    return int(std::abs(x - nearest) <= 1e-9 * std::max(1.0, std::abs(x)) ? nearest : std::ceil(x));
}

PixelBounds crop_window(const SceneNode& film, const RasterSize& raster) {
    PixelBounds bounds{0, 0, raster.width, raster.height};
    if (!film.has("crop")) return bounds;
    const std::vector<double> c = film.numbers("crop", 4, NumberRange::unit_interval());
    if (!(c[0] < c[1]) || !(c[2] < c[3])) film.fail_at("crop", "expected [x_min, x_max, y_min, y_max] with min < max");
    bounds.x0 = pixel_edge(raster.width, c[0]);
    bounds.x1 = std::max(bounds.x0 + 1, pixel_edge(raster.width, c[1]));
    bounds.y0 = pixel_edge(raster.height, c[2]);
    bounds.y1 = std::max(bounds.y0 + 1, pixel_edge(raster.height, c[3]));
    bounds.x1 = std::min(bounds.x1, raster.width);
    bounds.y1 = std::min(bounds.y1, raster.height);
    bounds.x0 = std::min(bounds.x0, bounds.x1 - 1);
    bounds.y0 = std::min(bounds.y0, bounds.y1 - 1);
    return bounds;
}

void load_film(const SceneNode& root, const SceneOverrides& overrides, LoadedScene& loaded, DefaultSections& defaults) {
    const SceneNode film = defaults.object_or_defaults(root, "film");
    RasterSize raster{640, 480};
    if (film.has("resolution")) {
        const auto r = film.numbers("resolution", 2, NumberRange::between(1, kMaxResolution));
        if (r[0] != std::floor(r[0]) || r[1] != std::floor(r[1]))
            film.fail_at("resolution", "expected whole pixel counts");
        raster = {int(r[0]), int(r[1])};
    }
    loaded.film.raster = raster;
    loaded.film.crop = crop_window(film, raster);
    loaded.spp = film.integer_or("spp", 16, NumberRange::between(1, kMaxSamplesPerPixel));
    loaded.film.half_float = film.choice_or("exr_pixel", "float", {"float", "half"}) == "half";
    if (auto aovs = film.optional_value("aovs")) {
        for (const SceneNode& item : aovs->elements()) {
            if (!item.json().is_string()) item.fail("expected an AOV name");
            try {  // one name at a time, so that an unknown name is reported where it is written
                for (Aov aov : parse_aov_list(item.json().string, item.path()))
                    if (std::find(loaded.film.aovs.begin(), loaded.film.aovs.end(), aov) == loaded.film.aovs.end())
                        loaded.film.aovs.push_back(aov);
            } catch (const InputError& error) {
                item.fail(error.problem());
            }
        }
    }
    for (Aov aov : overrides.extra_aovs)
        if (std::find(loaded.film.aovs.begin(), loaded.film.aovs.end(), aov) == loaded.film.aovs.end())
            loaded.film.aovs.push_back(aov);
    film.charge_at("resolution", Film::memory_bytes(loaded.film),
                   "a film of " + std::to_string(loaded.film.crop.width()) + "x" +
                       std::to_string(loaded.film.crop.height()) + " pixels with " +
                       std::to_string(loaded.film.aovs.size()) + " AOV(s)");
    loaded.display = film.string_or("display", "");
    loaded.view = film.string_or("view", "");
    try {  // a dry run: an unknown display or view would otherwise surface only when writing, after the render
        float probe[3] = {0, 0, 0};
        loaded.colours->to_display(probe, 1, 3, loaded.display, loaded.view);
    } catch (const InputError& error) {
        if (error.field() == "display" || error.field() == "view") film.fail_at(error.field(), error.problem());
        throw;
    }

    const SceneNode filter = defaults.object_or_defaults(film, "filter");
    loaded.filter_type = filter.string_or("type", "gaussian");
    loaded.filter = pixel_filter_registry().create(filter, "gaussian");
    film.finish();
}

void load_content(const SceneNode& root, const SceneOverrides& overrides, RenderScene& scene) {
    if (auto materials = root.optional_object("materials")) {
        materials->accept_all_keys();
        for (const std::string& name : materials->keys())
            scene.add_material(name, material_registry().create(materials->object(name)));
    }
    for (const SceneNode& light : root.object_array("lights")) {
        std::unique_ptr<Light> created = light_registry().create(light);
        // Light selection sums the powers in float: keep each well inside its range (1e38 overflowed it).
        if (!(created->power() <= kMaxLightPower)) {
            char power[32];
            std::snprintf(power, sizeof power, "%.3g", double(created->power()));
            light.fail(std::string("the light's power (") + power + ") exceeds the supported maximum of 1e30");
        }
        scene.add_light(std::move(created));
    }
    SceneDefinitions definitions(root.optional_object("definitions"), overrides, scene);
    const std::vector<SceneNode> objects = root.object_array("objects");
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const SceneNode& node = objects[i];
        const std::string name = node.string_or("name", "objects[" + std::to_string(i) + "]");
        if (node.has("instance")) {
            definitions.place(node, name);
        } else {
            SceneObject object = build_shaped_object(node, name, overrides, scene);
            object.to_world = parse_optional_transform(node, "transform");
            if (!placed_within_world(*object.shape, object.to_world))
                node.fail_at("transform", beyond_world_problem("the shape, transformed,"));
            // A shape that cannot bake its transform is traced as a placement (RenderScene::commit).
            if (!placement_record(object.to_world, 0)) node.fail_at("transform", kSingularInSinglePrecision);
            scene.add_object(std::move(object));
        }
        node.finish();
    }
}

}  // namespace

std::unique_ptr<LoadedScene> load_scene(const std::string& path, const SceneOverrides& overrides) {
    const auto start = std::chrono::steady_clock::now();
    auto loaded = std::make_unique<LoadedScene>();
    loaded->path = path;
    auto context = std::make_shared<SceneFileContext>();
    if (overrides.max_memory_bytes) context->memory = std::make_shared<MemoryBudget>(*overrides.max_memory_bytes);
    SceneDocument read = read_scene_document(path, overrides.max_scene_file_bytes, context->memory.get());
    const JsonValue& document = read.root;
    if (document.is_object()) apply_scene_settings(read.root, overrides.settings, context->memory.get());  // else the error below
    substitute_named_values(read.root, *context->memory);
    for (const SceneSetting& setting : overrides.settings)
        if (!setting.recorded_apart) loaded->settings.push_back(setting.text());
    context->file = path;
    context->directory = std::filesystem::absolute(std::filesystem::path(path)).parent_path();
    context->included_directories = std::move(read.included_directories);
    for (const std::filesystem::path& file : read.included_files) context->files->add(file);
    SceneNode root(document, "", context);
    if (!document.is_object()) root.fail("a scene file must contain a JSON object");
    // Reject misspelt sections before anything slow (mesh loading) happens.
    // "include" and "values" are gone by now, but named here for the spelling suggestions.
    for (const char* key : {"isotrace", "description", "include", "values", "colour", "film", "camera", "sampler",
                            "integrator", "materials", "lights", "definitions", "objects"})
        root.optional_value(key);
    root.finish();
    DefaultSections defaults;

    const int version = root.integer("isotrace");
    if (version != kSceneFormatVersion)
        root.fail_at("isotrace", "unsupported scene format version " + std::to_string(version) + " (this build reads " +
                                     std::to_string(kSceneFormatVersion) + ")");
    loaded->description = root.string_or("description", "");

    const SceneNode colour = defaults.object_or_defaults(root, "colour");
    const std::string working_space = colour.string_or("working_space", "ACEScg");
    try {
        loaded->colours = std::make_unique<ColourSystem>("", working_space);
    } catch (const InputError& error) {
        if (error.field() != "working_space") throw;  // a broken config is not the scene's fault
        colour.fail_at("working_space", error.problem());
    }
    colour.finish();
    context->colours = loaded->colours.get();

    load_film(root, overrides, *loaded, defaults);

    const SceneNode camera = root.object("camera");
    loaded->camera_type = camera.string_or("type", "");
    loaded->camera = camera_registry().create(camera, loaded->film.raster);

    const SceneNode sampler = defaults.object_or_defaults(root, "sampler");
    loaded->seed = sampler.unsigned_or("seed", 0);
    loaded->sampler_type = sampler.string_or("type", "sobol");
    loaded->sampler = sampler_registry().create(sampler, loaded->seed, "sobol");

    const SceneNode integrator = defaults.object_or_defaults(root, "integrator");
    loaded->integrator_type = integrator.string_or("type", "path");
    loaded->integrator = integrator_registry().create(integrator, "path");

    loaded->scene = std::make_unique<RenderScene>();
    load_content(root, overrides, *loaded->scene);
    loaded->referenced_files = context->files->sorted();
    loaded->parse_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    loaded->scene->commit();
    return loaded;
}

}  // namespace isotrace
