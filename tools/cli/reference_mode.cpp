#include "tools/cli/reference_mode.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "renderer/core/input_error.h"
#include "renderer/film/estimated_error.h"
#include "renderer/image/image_writer.h"
#include "tools/cli/build_description.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/scene_fingerprint.h"

namespace isotrace::cli {

void add_reference_options(CLI::App& command, bool& reference, std::optional<std::string>& target_error) {
    command.add_flag("--reference", reference,
                     "Render a reference image: the EXR gets the variance and sampleCount channels (full float) and "
                     "metadata to reproduce it bit for bit; prints the estimated relative error after each pass");
    command.add_option("--target-error", target_error,
                       "With --reference: stop at the first pass boundary (64, 128, 256, ... spp) where the estimated "
                       "relative error is at most this (0.01 = about 1 % noise); --spp and --time still bound it; "
                       "exit 3 when they stop the render before it")
        ->type_name("NUMBER>0");
}

ReferenceRequest parse_reference_request(bool reference, const std::optional<std::string>& target_error, bool resuming) {
    ReferenceRequest request;
    request.enabled = reference;
    if (target_error) {
        request.target_error = parse_positive_number(*target_error, "--target-error", "a relative error");
        if (!reference && !resuming)
            throw InputError({}, "--target-error", "needs --reference (the stop is decided from the variance that a "
                                                   "reference render records)");
    }
    return request;
}

void require_reference_output(const std::vector<std::string>& outputs) {
    if (std::none_of(outputs.begin(), outputs.end(),
                     [](const std::string& output) { return image_kind_for(output) == ImageKind::Exr; }))
        throw InputError({}, "--reference", "writes the mean, variance and sample count to an EXR: give -o NAME.exr");
}

void add_reference_channels(std::vector<Aov>& aovs) {
    for (Aov needed : {Aov::Variance, Aov::SampleCount})
        if (std::find(aovs.begin(), aovs.end(), needed) == aovs.end()) aovs.push_back(needed);
}

std::function<bool(const Film&)> reference_stop_rule(const ReferenceRequest& request, bool quiet) {
    return [request, quiet](const Film& film) {
        const double error = estimated_relative_error(film);
        const int spp = int(film.sample_count_range().min);
        const bool reached = request.target_error && spp >= kMinimumTargetErrorSpp && error <= *request.target_error;
        if (!quiet) {
            if (request.target_error)
                std::fprintf(stderr, "isotrace: %d spp: estimated relative error %.4g (target %.4g%s)%s\n", spp, error,
                             *request.target_error,
                             spp < kMinimumTargetErrorSpp
                                 ? (", checked from " + std::to_string(kMinimumTargetErrorSpp) + " spp").c_str()
                                 : "",
                             reached ? ": reached" : "");
            else
                std::fprintf(stderr, "isotrace: %d spp: estimated relative error %.4g\n", spp, error);
        }
        return reached;
    };
}

std::string unmet_target_warning(const ReferenceRequest& request, const RenderResult& result) {
    if (!request.target_error || result.stopped_at_pass_end || result.cancelled) return "";
    const double error = estimated_relative_error(*result.film);
    if (result.completed_spp >= kMinimumTargetErrorSpp && error <= *request.target_error) return "";
    char text[320];
    std::snprintf(text, sizeof text,
                  "the target error was not reached: estimated relative error %.4g at %d spp, target %.4g (%s); the "
                  "images are written",
                  error, result.completed_spp, *request.target_error,
                  result.out_of_time ? "the time budget --time ran out"
                  : result.completed_spp < kMinimumTargetErrorSpp
                      ? ("the sample limit came before " + std::to_string(kMinimumTargetErrorSpp) +
                         " spp, where the target is first checked").c_str()
                      : "the sample limit --spp was reached");
    return text;
}

namespace {

std::string format_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

// A word for a POSIX shell: in single quotes, each ' written as '\''.
std::string shell_quoted(const std::string& word) {
    std::string quoted = "'";
    for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::string reproduce_command(const ReferenceRequest& request, const ReferenceSettings& settings,
                              const LoadedScene& scene, const RenderResult& result) {
    if (result.partial)
        return "none: the render stopped inside a pass (time budget or interruption), so pixels have different "
               "sample counts (see sampleCount)";
    std::string common = "isotrace render " + std::filesystem::path(scene.path).filename().string() +
                         " --reference --res " + std::to_string(settings.resolution.width) + "x" +
                         std::to_string(settings.resolution.height) + " --seed " + std::to_string(settings.seed);
    for (const std::string& setting : scene.settings) common += " --set " + shell_quoted(setting);
    std::string command = common + " --spp " + std::to_string(result.completed_spp);
    if (result.stopped_at_pass_end) {
        command += "; or " + common + " --target-error " + format_number(*request.target_error);
        if (settings.spp_budget != kMaxSamplesPerPixel) command += " --spp " + std::to_string(settings.spp_budget);
    }
    return command;
}

}  // namespace

void add_reference_metadata(ImageMetadata& metadata, const ReferenceRequest& request, const ReferenceSettings& settings,
                            const LoadedScene& scene, const RenderResult& result) {
    metadata.set("isotrace:reference", std::int64_t(1));
    metadata.set("isotrace:scene_hash", scene_hash(scene));
    metadata.set("isotrace:commit", build_description().commit);
    metadata.set("isotrace:resolution", std::to_string(settings.resolution.width) + "x" +
                                            std::to_string(settings.resolution.height));
    metadata.set("isotrace:spp_budget", std::int64_t(settings.spp_budget));
    if (settings.time_budget_seconds) metadata.set("isotrace:time_budget_seconds", *settings.time_budget_seconds);
    if (request.target_error) metadata.set("isotrace:target_error", *request.target_error);
    metadata.set("isotrace:estimated_error", estimated_relative_error(*result.film));
    metadata.set("isotrace:estimated_error_definition",
                 std::string("sqrt(mean over pixels and R, G, B of variance / (|R, G, B| + 0.01)^2)"));
    metadata.set("isotrace:channels",
                 std::string("R, G, B: mean radiance; variance.R/G/B: variance of that mean (per-sample variance / "
                             "sampleCount); sampleCount: samples in the pixel"));
    metadata.set("isotrace:reproduce", reproduce_command(request, settings, scene, result));
}

}  // namespace isotrace::cli
