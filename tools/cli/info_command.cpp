#include <cstdio>

#include "geometry/mesh/mesh_deformer.h"
#include "renderer/colour/colour_system.h"
#include "renderer/plugin/camera.h"
#include "renderer/plugin/integrator.h"
#include "renderer/plugin/light.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/pixel_filter.h"
#include "renderer/plugin/sampler_registry.h"
#include "renderer/plugin/shape.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/core/printable.h"
#include "tools/cli/commands.h"
#include "tools/cli/render_warnings.h"
#include "tools/cli/scene_fingerprint.h"
#include "tools/cli/scene_options.h"

namespace isotrace::cli {
namespace {

template <class Registry>
void print_plugins(const Registry& registry) {
    std::printf("%s types:\n", registry.kind().c_str());
    for (const auto& [name, entry] : registry.entries()) std::printf("  %-22s %s\n", name.c_str(), entry.summary.c_str());
}

void print_all_plugins() {
    print_plugins(shape_registry());
    print_plugins(shape_wrapper_registry());
    print_plugins(material_registry());
    print_plugins(light_registry());
    print_plugins(camera_registry());
    print_plugins(integrator_registry());
    print_plugins(pixel_filter_registry());
    print_plugins(sampler_registry());
    print_plugins(mesh_deformer_registry());
}

// The displays and views of the OCIO config, the config's defaults marked, and the pair the scene's
// display-referred outputs use when a scene is given.
void print_views(const ColourSystem& colours, const LoadedScene* scene) {
    const std::string default_display = colours.default_display();
    std::string used_display, used_view;
    if (scene) {
        used_display = scene->display.empty() ? default_display : scene->display;
        used_view = scene->view.empty() ? colours.default_view(used_display) : scene->view;
    }
    const auto marks = [](bool is_default, bool used) {
        std::string text = is_default ? "default" : "";
        if (used) text += text.empty() ? "the scene's" : ", the scene's";
        return text.empty() ? text : "  (" + text + ")";
    };
    std::printf("OCIO config  %s\n", printable(colours.config_path()).c_str());
    for (const std::string& display : colours.displays()) {
        std::printf("display      %s%s\n", printable(display).c_str(),
                    marks(display == default_display, display == used_display).c_str());
        const std::string default_view = colours.default_view(display);
        for (const std::string& view : colours.views(display))
            std::printf("  view       %s%s\n", printable(view).c_str(),
                        marks(view == default_view, display == used_display && view == used_view).c_str());
    }
}

std::unique_ptr<LoadedScene> load_with_options(const std::string& path, const SceneOptions& options) {
    SceneOverrides overrides;
    add_scene_settings(options, overrides);
    return load_scene(path, overrides);
}

int run_info(const std::string& path, const SceneOptions& options) {
    const std::unique_ptr<LoadedScene> scene = load_with_options(path, options);
    const BuildStatistics& build = scene->scene->build_statistics();
    const Bounds3f bounds = scene->scene->bounds();
    std::printf("scene        %s%s%s\n", printable(path).c_str(), scene->description.empty() ? "" : " - ",
                printable(scene->description).c_str());
    std::printf("film         %dx%d (crop %d..%d x %d..%d), %d spp, %s filter, EXR %s\n", scene->film.raster.width,
                scene->film.raster.height, scene->film.crop.x0, scene->film.crop.x1, scene->film.crop.y0,
                scene->film.crop.y1, scene->spp, scene->filter_type.c_str(), scene->film.half_float ? "half" : "float");
    std::printf("scene hash   %s (the scene file and %zu referenced file(s), by content%s)\n", scene_hash(*scene).c_str(),
                scene->referenced_files.size(),
                scene->settings.empty() ? "" : (", and " + std::to_string(scene->settings.size()) + " --set value(s)").c_str());
    std::printf("camera       %s\n", scene->camera_type.c_str());
    std::printf("integrator   %s\n", scene->integrator_type.c_str());
    if (const std::string warning = light_left_out_warning(*scene); !warning.empty())
        std::fprintf(stderr, "isotrace: warning: %s\n", warning.c_str());
    std::printf("sampler      %s, seed %llu\n", scene->sampler_type.c_str(), (unsigned long long)scene->seed);
    std::printf("colour       working space %s, OCIO config %s\n", scene->colours->working_space().c_str(),
                scene->colours->config_path().c_str());
    std::printf("objects      %zu (%zu instanced), %zu light(s) of which %zu area light(s)\n", build.objects,
                build.instanced_objects, scene->scene->lights().size(), build.area_lights);
    if (build.placements > 0)
        std::printf("             %zu placement(s) of %zu shape(s) of definitions, each shape built once\n",
                    build.placements, build.placed_shapes);
    if (build.unsampled_emitters > 0)
        std::printf("             %zu emissive object(s) not reachable by light sampling (found by BSDF sampling only)\n",
                    build.unsampled_emitters);
    for (const auto& [type, count] : build.primitives_by_type) std::printf("  %-18s %zu primitive(s)\n", type.c_str(), count);
    std::printf("bounds       [%g %g %g] .. [%g %g %g]\n", bounds.lower.x, bounds.lower.y, bounds.lower.z,
                bounds.upper.x, bounds.upper.y, bounds.upper.z);
    std::printf("build        %.3f s, %.1f MiB in Embree, %.1f MiB in shapes, %.1f MiB in objects\n", build.seconds,
                double(build.embree_bytes) / (1 << 20), double(build.shape_bytes) / (1 << 20),
                double(build.object_bytes) / (1 << 20));
    return kExitOk;
}

}  // namespace

CommandRunner add_info_options(CLI::App* command) {
    auto path = std::make_shared<std::string>();
    auto plugins = std::make_shared<bool>(false);
    auto views = std::make_shared<bool>(false);
    command->add_option("scene", *path, "Scene file (JSON)")->check(CLI::ExistingFile);
    command->add_flag("--plugins", *plugins, "List every registered plugin type");
    command->add_flag("--views", *views,
                      "List the OCIO config's displays and views (for film.display and film.view), marking the "
                      "defaults and, with a scene, the pair it uses");
    auto options = std::make_shared<SceneOptions>();
    add_scene_options(*command, *options);
    return [path, plugins, views, options] {
        if (*plugins) {
            print_all_plugins();
            return kExitOk;
        }
        if (*views) {
            if (path->empty()) {
                print_views(ColourSystem(""), nullptr);
            } else {
                const std::unique_ptr<LoadedScene> scene = load_with_options(*path, *options);
                print_views(*scene->colours, scene.get());
            }
            return kExitOk;
        }
        if (path->empty()) throw CLI::RequiredError("scene");
        return run_info(*path, *options);
    };
}

}  // namespace isotrace::cli
