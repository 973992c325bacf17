#pragma once
// The options of every command that loads a scene file: --set PATH=VALUE, and --display and --view where the command
// writes display-referred images. Each stands for a scene setting (docs/scene-authoring.md).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "renderer/scene/loaded_scene.h"

namespace isotrace::cli {

struct SceneOptions {
    std::vector<std::string> sets;  // PATH=VALUE, in order
    std::string display, view;
};

enum class DisplayOptions { No, Yes };

void add_scene_options(CLI::App& command, SceneOptions& options, DisplayOptions display = DisplayOptions::No);

// The settings the options stand for, appended to `overrides`: --set in order, then --display and --view.
void add_scene_settings(const SceneOptions& options, SceneOverrides& overrides);

}  // namespace isotrace::cli
