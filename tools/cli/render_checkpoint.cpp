#include "tools/cli/render_checkpoint.h"

#include <cmath>

#include "renderer/core/input_error.h"
#include "renderer/core/version.h"
#include "renderer/render/checkpoint_file.h"
#include "tools/cli/command_helpers.h"
#include "tools/cli/scene_fingerprint.h"

namespace isotrace::cli {
namespace {

[[noreturn]] void reject(const std::string& checkpoint, const std::string& problem) {
    throw InputError({checkpoint}, "", problem);
}

}  // namespace

void save_checkpoint(const std::filesystem::path& path, const LoadedScene& scene, const PixelOptions& options,
                     const Film& film) {
    const SampleCountRange counts = film.sample_count_range();
    const PixelBounds& crop = film.bounds();
    const nlohmann::json metadata = {
        {"isotrace_version", kIsotraceVersion},
        {"scene", {{"path", scene.path}, {"files", scene_files(scene)}}},
        {"options",
         {{"spp", options.spp},
          {"resolution", {options.resolution.width, options.resolution.height}},
          {"seed", std::to_string(options.seed)},
          {"aovs", options.extra_aovs},
          {"reference", options.reference},
          {"target_error", options.target_error ? nlohmann::json(*options.target_error) : nlohmann::json()},
          {"set", options.settings}}},
        {"film",
         {{"crop", {crop.x0, crop.y0, crop.x1, crop.y1}},
          {"completed_spp", counts.min},
          {"max_spp", counts.max},
          {"samples", counts.total}}},
        {"pass_schedule",
         "passes end at 1, 2, 4, 8, ... samples, the first at the integrator's group of samples traced together; every "
         "pixel continues at its own sample count"},
    };
    // Replacing bytes that are not UTF-8 (a scene path or override given so) rather than refusing to save.
    write_checkpoint(path, {metadata.dump(1, ' ', false, nlohmann::json::error_handler_t::replace), film.state()});
}

ResumePoint read_resume_point(const std::filesystem::path& path) {
    const std::string source = path.string();
    CheckpointContents contents = read_checkpoint(path);
    ResumePoint resume;
    try {
        resume.metadata = nlohmann::json::parse(contents.metadata_json);
        const std::string version = resume.metadata.at("isotrace_version").get<std::string>();
        if (version != kIsotraceVersion)
            reject(source, "the checkpoint was written by isotrace " + version + "; this is isotrace " +
                               kIsotraceVersion + " (renders can only be resumed by the same version)");
        // Each value within the range the command line accepts: the checksum only says that these are the bytes
        // written, and a changed file can carry a matching one.
        const nlohmann::json& options = resume.metadata.at("options");
        const auto whole_number = [&](const nlohmann::json& value, const std::string& field) {
            if (!value.is_number_integer())
                throw InputError({source}, field, "expected a whole number, got " + value.dump());
            return value.dump();
        };
        const std::string spp = whole_number(options.at("spp"), "options.spp");
        if (options.at("spp").get<std::int64_t>() < 1 || options.at("spp").get<std::int64_t>() > kMaxSamplesPerPixel)
            throw InputError({source}, "options.spp",
                             spp + " is out of range (1 to " + std::to_string(kMaxSamplesPerPixel) + ")");
        resume.options.spp = options.at("spp").get<int>();
        const nlohmann::json& resolution = options.at("resolution");
        if (!resolution.is_array() || resolution.size() != 2)
            throw InputError({source}, "options.resolution", "expected [width, height], got " + resolution.dump());
        resume.options.resolution = parse_resolution(whole_number(resolution.at(0), "options.resolution") + "x" +
                                                         whole_number(resolution.at(1), "options.resolution"),
                                                     "options.resolution");
        resume.options.seed = parse_seed(options.at("seed").get<std::string>(), "options.seed");
        resume.options.extra_aovs = options.at("aovs").get<std::vector<std::string>>();
        // Absent from checkpoints written before reference mode existed: those were not reference renders.
        resume.options.reference = options.value("reference", false);
        if (options.contains("target_error") && !options.at("target_error").is_null()) {
            resume.options.target_error = options.at("target_error").get<double>();
            if (!(std::isfinite(*resume.options.target_error) && *resume.options.target_error > 0))
                throw InputError({source}, "options.target_error", "expected a finite number > 0");
        }
        // Absent from checkpoints written before scene overrides existed: those had none.
        if (options.contains("set")) resume.options.settings = options.at("set").get<std::vector<std::string>>();
        resume.metadata.at("scene").at("files").at(0).at("fnv1a64").get<std::string>();
    } catch (const nlohmann::json::exception& error) {
        reject(source, std::string("the checkpoint's metadata is incomplete: ") + error.what());
    } catch (const InputError& error) {  // the command line's parsers name the field, not the file
        if (!error.location().file.empty()) throw;
        throw InputError({source}, error.field(), error.problem());
    }
    resume.film_state = std::move(contents.film_state);
    return resume;
}

void check_same_scene(const ResumePoint& resume, const LoadedScene& scene, const std::string& checkpoint) {
    const nlohmann::json& recorded = resume.metadata.at("scene").at("files");
    const nlohmann::json current = scene_files(scene);
    const auto describe = [](const nlohmann::json& f) {
        return std::to_string(f.at("bytes").get<std::uint64_t>()) + " bytes, FNV-1a " + f.at("fnv1a64").get<std::string>();
    };
    const auto name = [](const nlohmann::json& f) { return f.at("path").get<std::string>(); };
    for (std::size_t i = 0; i < std::max(recorded.size(), current.size()); ++i) {
        if (i >= recorded.size())
            reject(checkpoint, "the scene now references " + name(current[i]) +
                                   ", which it did not when the checkpoint was written");
        if (i >= current.size()) reject(checkpoint, "the scene no longer references " + name(recorded[i]));
        if (recorded[i].at("bytes") != current[i].at("bytes") || recorded[i].at("fnv1a64") != current[i].at("fnv1a64"))
            reject(checkpoint, std::string(i == 0 ? "the scene file " : "the file ") + name(current[i]) +
                                   (i == 0 ? "" : ", referenced by the scene,") +
                                   " changed since the checkpoint was written (now " + describe(current[i]) +
                                   "; then " + describe(recorded[i]) + ")");
    }
}

}  // namespace isotrace::cli
