// isotrace depth: the range image of Tae-Eun Kim's "3D Shape Reconstruction based on Superquadrics and Single
// Z-buffer CSG Rendering" (the depth of the first hit as 256 grey levels) of a scene, as an 8-bit grey PNG.
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "renderer/core/input_error.h"
#include "renderer/core/version.h"
#include "renderer/image/image_writer.h"
#include "renderer/render/depth_map.h"
#include "renderer/render/range_image.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/commands.h"
#include "tools/cli/memory_limit_option.h"
#include "tools/cli/scene_options.h"
#include "tools/cli/thread_limit.h"

namespace isotrace::cli {
namespace {

struct DepthArguments {
    std::string scene;
    std::string output;
    std::string exr;
    std::optional<double> near, far;
    std::string resolution;
    std::string max_memory;
    int threads = 0;
    bool near_dark = false;
    bool quiet = false;
    SceneOptions scene_options;
};

// The mapping's ends: the user's, else the nearest and farthest hit.
DepthRange choose_range(const DepthArguments& args, const DepthMap& map) {
    const std::optional<DepthRange> hits = depth_range_of_hits(map);
    DepthRange range = hits.value_or(DepthRange{});
    if (args.near) range.near = float(*args.near);
    if (args.far) range.far = float(*args.far);
    range.near_is_bright = !args.near_dark;
    if (!(range.near <= range.far))
        throw InputError({}, args.far ? "--far" : "--near",
                         "the near depth " + std::to_string(range.near) + " lies beyond the far depth " +
                             std::to_string(range.far));
    return range;
}

std::string format_depth(float depth) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(depth));
    return text;
}

ImageMetadata make_metadata(const DepthArguments& args, const DepthRange& range) {
    ImageMetadata metadata;
    metadata.set("Software", std::string("isotrace ") + kIsotraceVersion);
    metadata.set("isotrace:scene", args.scene);
    // Text, because PNG keeps only text attributes.
    metadata.set("isotrace:depth_near", format_depth(range.near));
    metadata.set("isotrace:depth_far", format_depth(range.far));
    metadata.set("isotrace:depth_near_grey", range.near_is_bright ? "255" : "0");
    return metadata;
}

int run_depth(const DepthArguments& args) {
    require_extension(args.output, ".png", "--output");
    std::vector<NamedPath> outputs{{args.output, "--output"}};
    if (!args.exr.empty()) {
        require_extension(args.exr, ".exr", "--exr");
        outputs.push_back({args.exr, "--exr"});
    }
    check_output_paths(outputs, {{args.scene, "the scene"}});
    // Depths are single-precision floats: an infinite end (or one beyond float's range) maps every depth to one grey.
    if (args.near && !std::isfinite(float(*args.near))) throw InputError({}, "--near", "must be a finite depth");
    if (args.far && !std::isfinite(float(*args.far))) throw InputError({}, "--far", "must be a finite depth");
    if (args.near && args.far && !(*args.near < *args.far))
        throw InputError({}, "--far", "must be greater than --near");
    // A missing image module fails now, not after the depth map.
    image_encoder_for(args.output);
    if (!args.exr.empty()) image_encoder_for(args.exr);
    SceneOverrides overrides;
    add_scene_settings(args.scene_options, overrides);
    if (!args.resolution.empty()) overrides.settings.push_back(resolution_setting(parse_resolution(args.resolution, "--res")));
    overrides.max_memory_bytes = max_memory_bytes(args.max_memory);

    const int threads = args.threads > 0 ? args.threads : tbb::info::default_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    const std::unique_ptr<LoadedScene> scene = load_scene(args.scene, overrides);
    check_output_paths(outputs, scene_inputs(*scene));
    const DepthMap map = render_depth_map(*scene);
    const DepthRange range = choose_range(args, map);
    const ImageMetadata metadata = make_metadata(args, range);

    write_grey8_image(args.output, map.window.width(), map.window.height(), range_image(map, range), metadata);
    if (!args.exr.empty()) {
        ImageBuffer raw{map.window.width(), map.window.height(), {"Z"}, map.depth};
        write_exr(args.exr, raw, {scene->film.raster, map.window.x0, map.window.y0}, false, metadata);
    }
    if (!args.quiet) {
        std::size_t hits = 0;
        for (float d : map.depth) hits += std::isfinite(d) ? 1 : 0;
        std::fprintf(stderr, "isotrace: %s: %dx%d, %zu of %zu pixels hit, grey 255 at depth %g, 0 at depth %g\n",
                     args.scene.c_str(), map.window.width(), map.window.height(), hits, map.depth.size(),
                     double(range.near), double(range.far));
        std::fprintf(stderr, "wrote %s\n", args.output.c_str());
        if (!args.exr.empty()) std::fprintf(stderr, "wrote %s\n", args.exr.c_str());
    }
    return kExitOk;
}

}  // namespace

CommandRunner add_depth_options(CLI::App* command) {
    auto args = std::make_shared<DepthArguments>();
    command->footer("The range image of T.-E. Kim, \"3D Shape Reconstruction based on Superquadrics and Single "
                    "Z-buffer CSG Rendering\": g = (Z - Zmin) * 256 / (Zmax - Zmin), clamped to 0..255, with Z "
                    "growing towards the viewer; pixels that hit nothing are 0.");
    command->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
    command->add_option("-o,--output", args->output, "Range image, 8-bit grey PNG")->type_name("PATH")->required();
    command->add_option("--near", args->near, "Depth mapped to grey 255 (default: the nearest hit)");
    command->add_option("--far", args->far, "Depth mapped to grey 0 (default: the farthest hit)");
    command->add_flag("--near-dark", args->near_dark,
                      "Read the range image's Z as the depth itself: near = black (0), far and background = white "
                      "(255)");
    command->add_option("--exr", args->exr, "Also write the raw view depth Z (world units, inf = no hit) as EXR")
        ->type_name("PATH");
    command->add_option("--res", args->resolution,
                        "Resolution WIDTHxHEIGHT, each side 1 to 65536 (sets film.resolution)")
        ->type_name("WIDTHxHEIGHT");
    add_max_memory_option(*command, args->max_memory);
    add_threads_option(*command, args->threads);
    command->add_flag("-q,--quiet", args->quiet, "No summary on stderr");
    add_scene_options(*command, args->scene_options);
    return [args] { return run_depth(*args); };
}

}  // namespace isotrace::cli
