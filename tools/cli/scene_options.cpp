#include "tools/cli/scene_options.h"

#include <nlohmann/json.hpp>

namespace isotrace::cli {

void add_scene_options(CLI::App& command, SceneOptions& options, DisplayOptions display) {
    command
        .add_option("--set", options.sets,
                    "Replace a scene value: PATH=VALUE, e.g. film.spp=256, camera.fov=30, objects.dog.material=\"gold\" "
                    "(keys separated by dots, array elements by index or \"name\"; VALUE is JSON, a bare word a "
                    "string); repeat for several")
        ->type_name("PATH=VALUE")
        ->allow_extra_args(false);  // one value per --set: the next word is the scene or another option
    if (display == DisplayOptions::No) return;
    command.add_option("--display", options.display, "OCIO display of PNG/JPEG/TIFF outputs (sets film.display)")
        ->type_name("NAME");
    command.add_option("--view", options.view, "OCIO view of PNG/JPEG/TIFF outputs (sets film.view)")->type_name("NAME");
}

namespace {

// A name as a JSON string (a name that is not UTF-8 keeps replacement characters, which the loader then refuses).
std::string json_string(const std::string& name) {
    return nlohmann::json(name).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace

void add_scene_settings(const SceneOptions& options, SceneOverrides& overrides) {
    for (const std::string& argument : options.sets) overrides.settings.push_back(parse_scene_setting(argument));
    if (!options.display.empty())
        overrides.settings.push_back(
            shortcut_setting("film.display", json_string(options.display), "--display " + options.display));
    if (!options.view.empty())
        overrides.settings.push_back(
            shortcut_setting("film.view", json_string(options.view), "--view " + options.view));
}

}  // namespace isotrace::cli
