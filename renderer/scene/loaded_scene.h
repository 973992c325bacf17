#pragma once
// Everything a render needs, created from one scene file.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/colour/colour_system.h"
#include "renderer/film/film.h"
#include "renderer/params/json_document.h"
#include "renderer/plugin/camera.h"
#include "renderer/plugin/integrator.h"
#include "renderer/plugin/pixel_filter.h"
#include "renderer/sampling/sampler.h"
#include "renderer/scene/render_scene.h"
#include "renderer/scene/scene_settings.h"

namespace isotrace {

// The most samples per pixel a scene or --spp may ask for; also the budget of a render that only a time budget
// or a target error ends ("no sample limit").
constexpr int kMaxSamplesPerPixel = 1 << 24;

// Command-line values that replace the scene's.
struct SceneOverrides {
    // Scene values replaced before the scene is validated (--set, --spp, ...), in order.
    std::vector<SceneSetting> settings;
    std::vector<Aov> extra_aovs;
    // Memory limit for the estimates charged before large allocations (film, textures, generated elements);
    // unset = MemoryBudget's default, 80 % of physical memory.
    std::optional<std::uint64_t> max_memory_bytes;
    std::uint64_t max_scene_file_bytes = kDefaultMaxJsonFileBytes;
    // Called with every shape as it is created, before the scene is committed; returns the shape to use in its
    // place (the object's transform and material stay). isotrace bench traces blob groups as their tessellation.
    std::function<std::unique_ptr<Shape>(std::unique_ptr<Shape>)> replace_shape;
};

struct LoadedScene {
    std::string path;
    std::string description;
    std::unique_ptr<ColourSystem> colours;
    std::unique_ptr<RenderScene> scene;
    std::unique_ptr<Camera> camera;
    std::unique_ptr<Integrator> integrator;
    std::unique_ptr<Sampler> sampler;
    std::unique_ptr<PixelFilter> filter;
    FilmSettings film;
    int spp = 16;
    std::uint64_t seed = 0;
    std::string camera_type, integrator_type, sampler_type, filter_type;
    std::string display, view;  // for display-referred outputs; empty = the config's defaults
    std::vector<std::filesystem::path> referenced_files;  // external files the scene names or includes, sorted
    // The settings applied to it as PATH=VALUE, in order, but for those recorded apart (--spp, --res, --seed).
    std::vector<std::string> settings;
    double parse_seconds = 0;   // reading and validating the file, creating plugins and loading meshes
};

// Reads the scene and the files it includes, applies the overrides' settings, validates the result and builds its
// acceleration structures. Throws InputError for bad input.
std::unique_ptr<LoadedScene> load_scene(const std::string& path, const SceneOverrides& overrides = {});

}  // namespace isotrace
