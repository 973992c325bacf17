#pragma once
// isotrace render --reference [--target-error E]: a render meant as a reference image (docs/reference-images.md).
// It writes the variance and sample-count channels beside the mean, in full float, with metadata enough to
// reproduce it bit for bit, and with --target-error it stops at the first pass boundary (1, 2, 4, ... spp, from
// kMinimumTargetErrorSpp on) where the estimated relative error (renderer/film/estimated_error.h) is at most E.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "renderer/film/film.h"
#include "renderer/image/image_metadata.h"
#include "renderer/render/tile_renderer.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace::cli {

// Below this many samples per pixel a variance estimate is too rough to stop on (a pixel whose few samples all
// missed a bright, rare path looks noiseless).
inline constexpr int kMinimumTargetErrorSpp = 64;

struct ReferenceRequest {
    bool enabled = false;
    std::optional<double> target_error;
};

// Registers --reference and --target-error (kept as text for parse_reference_request).
void add_reference_options(CLI::App& command, bool& reference, std::optional<std::string>& target_error);

// Checks --reference and --target-error before any work: the target must be a finite number > 0 and needs
// --reference, unless `resuming` (the checkpoint then says whether the render is a reference). Throws InputError.
ReferenceRequest parse_reference_request(bool reference, const std::optional<std::string>& target_error, bool resuming);

// A reference needs an .exr among the outputs; throws InputError otherwise.
void require_reference_output(const std::vector<std::string>& outputs);

// Adds the variance and sample_count AOVs to `aovs` unless already there.
void add_reference_channels(std::vector<Aov>& aovs);

// RenderOptions::stop_at_pass_end for a reference render: prints the estimate at each pass boundary to stderr
// (unless quiet) and ends the render once it reaches the target, if there is one.
std::function<bool(const Film&)> reference_stop_rule(const ReferenceRequest& request, bool quiet);

// A render with a target error that ended before reaching it (by its sample limit or time budget): the warning to
// print, with the error reached and the target; "" when the target was met or there is none. A render that
// stopped at its sample limit with the error at most the target, checked or not, meets it.
std::string unmet_target_warning(const ReferenceRequest& request, const RenderResult& result);

// The pixel-affecting options of the render, for the metadata.
struct ReferenceSettings {
    RasterSize resolution;
    std::uint64_t seed = 0;
    int spp_budget = 0;          // --spp (or the scene's); kMaxSamplesPerPixel when the target error or --time lifted it
    std::optional<double> time_budget_seconds;
};

// isotrace:reference, isotrace:scene_hash, isotrace:commit, isotrace:target_error, isotrace:estimated_error,
// isotrace:channels (what variance.* and sampleCount hold) and isotrace:reproduce (a command that renders the
// same pixels, or why there is none).
void add_reference_metadata(ImageMetadata& metadata, const ReferenceRequest& request, const ReferenceSettings& settings,
                            const LoadedScene& scene, const RenderResult& result);

}  // namespace isotrace::cli
