#pragma once
// Command-line overrides of scene values: `--set PATH=VALUE` and the shortcut options that stand for one
// (--spp for film.spp, ...). Applied to the merged scene document before the loader validates it, so a value set
// here is checked exactly like one written in the file (docs/scene-authoring.md).
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/params/json_document.h"
#include "renderer/plugin/camera.h"

namespace isotrace {

class MemoryBudget;

// Bounds on one override: the path's length and number of keys, the value's length.
constexpr std::size_t kMaxSettingPathBytes = 1024;
constexpr std::size_t kMaxSettingPathKeys = 32;
constexpr std::size_t kMaxSettingValueBytes = std::size_t(1) << 16;
constexpr std::size_t kMaxSettings = 4096;

struct SceneSetting {
    std::string path;    // dot-separated keys; an array element by index or by its "name": "objects.dog.material"
    std::string value;   // JSON text; text that is not JSON and does not start like an array, object or string is a string
    std::string origin;  // the option as given, which messages name as the value's file: "--set film.spp=64", "--spp 64"
    int path_column = 0;   // where `path` starts in `origin` (1-based); 0 for a shortcut
    int value_column = 0;  // where `value` starts in `origin`
    bool create_sections = false;  // a shortcut: objects missing along the path are created
    // --spp, --res and --seed: recorded as options of their own (image metadata, checkpoints), not as overrides.
    bool recorded_apart = false;

    // "PATH=VALUE", as the scene hash, image metadata and checkpoints record it.
    std::string text() const { return path + "=" + value; }
};

// `--set PATH=VALUE` (`argument` is PATH=VALUE); throws InputError without a '='.
SceneSetting parse_scene_setting(const std::string& argument);

// A shortcut option standing for `path` = `value` (JSON text), given as `origin` ("--spp 64").
SceneSetting shortcut_setting(std::string path, std::string value, std::string origin);

// The render options that stand for a setting, recorded apart from the other overrides.
SceneSetting spp_setting(int spp);                 // film.spp, as "--spp N"
SceneSetting resolution_setting(RasterSize size);  // film.resolution, as "--res WxH"
SceneSetting seed_setting(std::uint64_t seed);     // sampler.seed, as "--seed N"

// Applies the settings in order (a later one wins). Every key of a path but the last must exist, unless the setting
// creates sections; the last may be new (the loader then reports it if it is unknown). Throws InputError at the
// setting for a path that leads nowhere, with a spelling suggestion. The values' trees are charged to `memory`.
void apply_scene_settings(JsonValue& document, const std::vector<SceneSetting>& settings, MemoryBudget* memory = nullptr);

}  // namespace isotrace
