// isotrace diff: how far a test image is from a reference (RMSE, relative MSE, PSNR, SSIM, FLIP), with a
// false-colour error map and thresholds to gate another renderer's CI on; --ztest: Mitsuba 3's per-pixel test of
// a low-budget render against a reference's mean and variance.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "renderer/core/input_error.h"
#include "renderer/core/version.h"
#include "renderer/image/image_writer.h"
#include "renderer/image_compare/error_map.h"
#include "renderer/image_compare/flip.h"
#include "renderer/image_compare/image_channels.h"
#include "renderer/image_compare/pixel_error.h"
#include "renderer/image_compare/ssim.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/commands.h"
#include "tools/cli/diff_thresholds.h"
#include "tools/cli/diff_z_test_input.h"
#include "tools/cli/memory_limit_option.h"

namespace isotrace::cli {
namespace {

struct DiffArguments {
    std::string reference, test;
    std::string json, error_map;
    std::string error_map_metric = "flip";
    std::vector<std::string> fail;
    double pixels_per_degree = kFlipDefaultPixelsPerDegree;
    bool z_test = false;
    std::optional<int> test_spp;
    ZTestSettings z_settings;
    std::string max_memory;
    bool quiet = false;
};

// Resident bytes per pixel the comparison takes beside the two decoded images (colour images, SSIM and FLIP
// buffers, the error map), measured as the peak of `isotrace diff` between 1000x1000 and 2000x2000 images.
constexpr std::uint64_t kComparisonBytesPerPixel = 144;

std::string describe_size(const ImageFile& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void require_comparable(const ImageFile& a, const std::string& a_path, const ImageFile& b, const std::string& b_path,
                        bool same_channels) {
    if (a.width != b.width || a.height != b.height)
        throw InputError({}, "", "images of different size: " + a_path + " is " + describe_size(a) + ", " + b_path +
                                     " is " + describe_size(b));
    if (a.display_referred != b.display_referred) {
        const auto kind = [](const ImageFile& f) {
            return f.display_referred ? "display-referred (integer pixels)" : "scene-linear (float pixels)";
        };
        throw InputError({}, "", a_path + " is " + kind(a) + " but " + b_path + " is " + kind(b) +
                                     ": compare an EXR with an EXR, a PNG with a PNG");
    }
    if (!same_channels) return;
    std::vector<std::string> ca = a.channels, cb = b.channels;
    std::sort(ca.begin(), ca.end());
    std::sort(cb.begin(), cb.end());
    if (ca == cb) return;
    const auto only = [](const std::vector<std::string>& x, const std::vector<std::string>& y) {
        std::string list;
        for (const std::string& c : x)
            if (!std::binary_search(y.begin(), y.end(), c)) list += (list.empty() ? "" : ", ") + c;
        return list.empty() ? std::string("none") : list;
    };
    throw InputError({}, "", "the images have different channels: only in " + a_path + ": " + only(ca, cb) +
                                 "; only in " + b_path + ": " + only(cb, ca));
}

struct Comparison {
    std::map<std::string, double> values;
    bool display_referred = false;
    double psnr_peak = 1, ssim_range = 1;
    FlipExposures exposures;
    std::vector<float> flip_map, ssim_map;
};

Comparison compare(const RgbImage& reference, const RgbImage& test, bool display_referred, double ppd) {
    Comparison c;
    c.display_referred = display_referred;
    c.values["rmse"] = rmse(reference, test);
    c.values["relmse"] = relative_mse(reference, test);
    c.psnr_peak = psnr_peak(reference, display_referred);
    c.values["psnr"] = psnr(reference, test, c.psnr_peak);
    const std::vector<float> y_reference = luminance_plane(reference), y_test = luminance_plane(test);
    const float brightest = *std::max_element(y_reference.begin(), y_reference.end());
    c.ssim_range = display_referred || !(brightest > 0) ? 1.0 : double(brightest);
    c.ssim_map = ssim_map(y_reference, y_test, reference.width, reference.height, c.ssim_range);
    c.values["ssim"] = mean_ssim(c.ssim_map);
    if (display_referred) {
        c.flip_map = ldr_flip(reference, test, ppd);
    } else {
        c.exposures = hdr_flip_exposures(reference);
        c.flip_map = hdr_flip(reference, test, ppd, c.exposures);
    }
    double flip_sum = 0;
    for (float v : c.flip_map) flip_sum += v;
    c.values["flip"] = flip_sum / double(c.flip_map.size());
    return c;
}

std::string flip_description(const Comparison& c, double ppd) {
    char text[200];
    if (c.display_referred)
        std::snprintf(text, sizeof text, "LDR-FLIP, mean, %.1f pixels per degree", ppd);
    else
        std::snprintf(text, sizeof text, "HDR-FLIP, mean, %.1f pixels per degree, %d exposures %.3f to %.3f", ppd,
                      c.exposures.count, c.exposures.start, c.exposures.stop);
    return text;
}

void print_comparison(const DiffArguments& args, const Comparison& c) {
    std::printf("reference %s (%s)\ntest      %s\n", args.reference.c_str(),
                c.display_referred ? "display-referred sRGB" : "scene-linear, compared as linear sRGB", args.test.c_str());
    std::printf("rmse    %.6g\n", c.values.at("rmse"));
    std::printf("relmse  %.6g   (pbrt-v4 MRSE: mean of (B - A)^2 / (A + 0.01)^2)\n", c.values.at("relmse"));
    std::printf("psnr    %.6g dB   (peak %.6g%s)\n", c.values.at("psnr"), c.psnr_peak,
                c.display_referred ? "" : ", the reference's largest value");
    std::printf("ssim    %.6g   (luminance, 11x11 Gaussian window sigma 1.5, dynamic range %.6g)\n",
                c.values.at("ssim"), c.ssim_range);
    std::printf("flip    %.6g   (%s)\n", c.values.at("flip"), flip_description(c, args.pixels_per_degree).c_str());
}

// JSON has no infinity: PSNR of identical images is written as the string "inf".
nlohmann::json number(double value) {
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    return value;
}

nlohmann::json comparison_json(const DiffArguments& args, const Comparison& c, int width, int height,
                               const std::vector<std::string>& broken) {
    nlohmann::json metrics;
    for (const auto& [name, value] : c.values) metrics[name] = number(value);
    nlohmann::json flip = {{"mode", c.display_referred ? "ldr" : "hdr"}, {"pixels_per_degree", args.pixels_per_degree}};
    if (!c.display_referred)
        flip["exposures"] = {{"start", c.exposures.start}, {"stop", c.exposures.stop}, {"count", c.exposures.count}};
    return {{"reference", args.reference}, {"test", args.test}, {"width", width}, {"height", height},
            {"encoding", c.display_referred ? "display-referred sRGB" : "scene-linear"}, {"metrics", metrics},
            {"psnr_peak", c.psnr_peak}, {"ssim_dynamic_range", c.ssim_range}, {"flip", flip},
            {"relmse_epsilon", kRelativeMseEpsilon}, {"broken_thresholds", broken}, {"isotrace", kIsotraceVersion}};
}

// The per-pixel picture of a metric, and the value shown brightest.
struct ErrorPicture {
    std::vector<float> values;
    double full_scale = 1;
    std::string description;
};

ErrorPicture error_picture(const std::string& metric, const RgbImage& reference, const RgbImage& test,
                           const Comparison& c) {
    ErrorPicture picture;
    if (metric == "flip") {
        picture = {c.flip_map, 1.0, "per-pixel FLIP, 0 to 1"};
    } else if (metric == "ssim") {
        picture.values.resize(c.ssim_map.size());
        for (std::size_t i = 0; i < c.ssim_map.size(); ++i) picture.values[i] = 1 - c.ssim_map[i];
        picture.description = "1 - per-pixel SSIM, 0 to 1";
    } else {
        const std::vector<float> y_reference = luminance_plane(reference), y_test = luminance_plane(test);
        picture.values.resize(y_reference.size());
        const bool relative = metric == "relmse";
        for (std::size_t i = 0; i < y_reference.size(); ++i) {
            const float difference = std::abs(y_test[i] - y_reference[i]);
            picture.values[i] = relative ? difference / float(std::abs(y_reference[i]) + kRelativeMseEpsilon) : difference;
        }
        const float largest = *std::max_element(picture.values.begin(), picture.values.end());
        picture.full_scale = largest > 0 ? double(largest) : 1.0;
        char text[120];
        std::snprintf(text, sizeof text, "%s, 0 to %.6g",
                      relative ? "|B - A| / (A + 0.01) of the luminance" : "|B - A| of the luminance", picture.full_scale);
        picture.description = text;
    }
    return picture;
}

void write_error_map(const DiffArguments& args, int width, int height, const ErrorPicture& picture) {
    ImageMetadata metadata;
    metadata.set("Software", std::string("isotrace ") + kIsotraceVersion);
    metadata.set("isotrace:diff_reference", args.reference);
    metadata.set("isotrace:diff_test", args.test);
    metadata.set("isotrace:error_map", picture.description);
    write_rgb8_image(args.error_map, width, height, false_colour(picture.values, picture.full_scale), metadata);
    if (!args.quiet) std::fprintf(stderr, "wrote %s (%s)\n", args.error_map.c_str(), picture.description.c_str());
}

std::string level_name(int edge) {
    return edge == 1 ? "pixels" : std::to_string(edge) + "x" + std::to_string(edge) + " blocks";
}

void print_z_test(const DiffArguments& args, const ZTestResult& result) {
    std::printf("z-test (each level needs %.2f %% of its tests to pass; significance %g over the levels): %s\n",
                100 * args.z_settings.required_pass_fraction, args.z_settings.significance,
                result.passed ? "pass" : "FAIL");
    std::printf("  %-14s %8s %8s %9s %10s %10s\n", "level", "tests", "failed", "passed %", "alpha", "min p");
    for (const ZTestLevel& level : result.levels)
        std::printf("  %-14s %8lld %8lld %9.3f %10.3g %10.3g  %s\n", level_name(level.edge).c_str(),
                    static_cast<long long>(level.tests), static_cast<long long>(level.failed), 100 * level.pass_fraction,
                    level.alpha, level.min_p_value, level.passed ? "pass" : "FAIL");
    if (result.worst.empty()) return;
    std::printf("most significant failures (block: top-left pixel and mean values):\n");
    for (const ZTestFailure& f : result.worst)
        std::printf("  %-14s at %d,%d %c: test %.6g, reference %.6g (%+.2f %%), z %.2f, p %.3g\n",
                    level_name(f.edge).c_str(), f.x, f.y, "RGB"[f.channel], f.test, f.reference,
                    f.reference != 0 ? 100 * (f.test - f.reference) / std::abs(f.reference) : 0.0, f.z, f.p_value);
}

nlohmann::json z_test_json(const DiffArguments& args, const ZTestResult& result) {
    nlohmann::json levels = nlohmann::json::array(), worst = nlohmann::json::array();
    for (const ZTestLevel& l : result.levels)
        levels.push_back({{"block_edge", l.edge}, {"tests", l.tests}, {"failed", l.failed}, {"alpha", l.alpha},
                          {"min_p_value", l.min_p_value}, {"pass_fraction", l.pass_fraction}, {"passed", l.passed}});
    for (const ZTestFailure& f : result.worst)
        worst.push_back({{"block_edge", f.edge}, {"x", f.x}, {"y", f.y}, {"channel", std::string(1, "RGB"[f.channel])},
                         {"test", f.test}, {"reference", f.reference}, {"z", f.z}, {"p_value", f.p_value}});
    return {{"reference", args.reference}, {"test", args.test}, {"significance", args.z_settings.significance},
            {"required_pass_fraction", args.z_settings.required_pass_fraction},
            {"variance_floor", args.z_settings.variance_floor}, {"levels", levels}, {"worst_failures", worst},
            {"passed", result.passed}, {"isotrace", kIsotraceVersion}};
}

int run_z_test(const DiffArguments& args, const ImageFile& reference, const ImageFile& test) {
    require_comparable(reference, args.reference, test, args.test, false);
    // Per-channel statistics: both images must hold the same primaries.
    if (reference.chromaticities != test.chromaticities)
        throw InputError({}, "", args.reference + " and " + args.test + " have different chromaticities (primaries)");
    const ZTestInput input = z_test_input(reference, args.reference, test, args.test, args.test_spp);
    const ZTestResult result = z_test(input, args.z_settings);
    print_z_test(args, result);
    if (!args.json.empty()) write_text_output(args.json, z_test_json(args, result).dump(2) + "\n");
    if (!args.error_map.empty()) {
        ErrorPicture picture{result.failed_per_pixel, 3.0, "failing pixel channels per pixel, 0 to 3"};
        write_error_map(args, input.test.width, input.test.height, picture);
    }
    return result.passed ? kExitOk : kExitNotMet;
}

int run_diff(const DiffArguments& args, bool error_map_metric_given) {
    std::vector<Threshold> thresholds;
    for (const std::string& text : args.fail) thresholds.push_back(parse_threshold(text));
    if (args.z_test && !thresholds.empty())
        throw InputError({}, "--fail", "not with --ztest, whose pass mark is the fraction of passing pixels");
    if (args.z_test && error_map_metric_given)
        throw InputError({}, "--error-map-metric", "not with --ztest, whose map shows the failing channels");
    require_metric_name(args.error_map_metric, "--error-map-metric");
    if (!args.error_map.empty()) require_extension(args.error_map, ".png", "--error-map");
    std::vector<NamedPath> outputs;
    if (!args.json.empty()) outputs.push_back({args.json, "--json"});
    if (!args.error_map.empty()) outputs.push_back({args.error_map, "--error-map"});
    check_output_paths(outputs, {{args.reference, "the reference image"}, {args.test, "the test image"}});

    MemoryBudget memory(max_memory_bytes(args.max_memory).value_or(MemoryBudget::default_limit_bytes()));
    const ImageFile reference_file = read_image_for_comparison(args.reference, memory);
    const ImageFile test_file = read_image_for_comparison(args.test, memory, kComparisonBytesPerPixel);
    if (args.z_test) return run_z_test(args, reference_file, test_file);

    require_comparable(reference_file, args.reference, test_file, args.test, true);
    const bool display = reference_file.display_referred;
    const RgbImage reference = display ? colour_of(reference_file, args.reference)
                                       : linear_srgb_colour_of(reference_file, args.reference);
    const RgbImage test = display ? colour_of(test_file, args.test) : linear_srgb_colour_of(test_file, args.test);
    const Comparison comparison = compare(reference, test, display, args.pixels_per_degree);
    const std::vector<std::string> broken = broken_thresholds(thresholds, comparison.values);

    print_comparison(args, comparison);
    if (!args.json.empty())
        write_text_output(args.json,
                              comparison_json(args, comparison, reference.width, reference.height, broken).dump(2) + "\n");
    if (!args.error_map.empty())
        write_error_map(args, reference.width, reference.height,
                        error_picture(args.error_map_metric, reference, test, comparison));
    for (const std::string& line : broken) std::fprintf(stderr, "isotrace diff: threshold broken: %s\n", line.c_str());
    return broken.empty() ? kExitOk : kExitNotMet;
}

}  // namespace

CommandRunner add_diff_options(CLI::App* command) {
    auto args = std::make_shared<DiffArguments>();
    command->footer("Metrics: RMSE, relative MSE, PSNR, SSIM and FLIP of test image B against reference A; --ztest: "
                    "a statistical test of a low-budget render against a reference's mean and variance. Exit codes: "
                    "0 every threshold holds (the z-test passes), 3 a threshold or the z-test fails, 2 bad input.");
    command->add_option("reference", args->reference, "Reference image A (EXR, PNG or any format OpenImageIO reads)")
        ->required();
    command->add_option("test", args->test, "Test image B, the same size, channels and kind (linear/display) as A")
        ->required();
    command->add_option("--json", args->json, "Also write the figures as JSON to this file")->type_name("PATH");
    command->add_option("--error-map", args->error_map, "Write a false-colour (magma-like) error map, PNG")
        ->type_name("PATH");
    CLI::Option* metric = command->add_option(
        "--error-map-metric", args->error_map_metric,
        "What the error map shows: flip (default, per-pixel FLIP), ssim (1 - SSIM), rmse or psnr (|B - A| of the "
        "luminance), relmse (|B - A| / (A + 0.01) of the luminance)");
    metric->type_name("METRIC");
    command->add_option("--fail", args->fail,
                        "METRIC=VALUE: exit 3 if the metric is worse than VALUE (above it; psnr and ssim: below); "
                        "repeatable")
        ->type_name("METRIC=VALUE")
        ->take_all()
        ->allow_extra_args(false);
    command->add_option("--ppd", args->pixels_per_degree, "FLIP's pixels per degree of visual angle (default 67: a 0.7 m "
                                                          "wide 4K monitor at 0.7 m)")
        ->check(CLI::Range(1.0, 1000.0));
    command->add_flag("--ztest", args->z_test,
                      "Per-pixel and per-block z-test of B (a low-budget render with another seed) against A's mean, "
                      "variance and sampleCount channels (isotrace render --reference), using B's variance channels "
                      "too when it has them; exit 3 unless 99.75 % of the tests pass at every level");
    command->add_option("--test-spp", args->test_spp, "--ztest: B's samples per pixel, if it has no sampleCount channel "
                                                      "or isotrace:spp metadata")
        ->check(CLI::Range(1, 1 << 30));
    command->add_option("--significance", args->z_settings.significance,
                        "--ztest: family-wise significance, split over the levels (pixels, block sizes) and "
                        "Sidak-corrected within each (default 0.01)")
        ->check(CLI::Range(1e-12, 0.5));
    command->add_option("--variance-floor", args->z_settings.variance_floor,
                        "--ztest: smallest per-sample variance (default 1e-4, Mitsuba's)")
        ->check(CLI::Range(0.0, 1e30));
    add_max_memory_option(*command, args->max_memory);
    command->add_flag("-q,--quiet", args->quiet, "No note on stderr about the files written");
    return [args, metric] { return run_diff(*args, metric->count() > 0); };
}

}  // namespace isotrace::cli
