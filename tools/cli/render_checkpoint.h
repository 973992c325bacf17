#pragma once
// What isotrace render keeps in a checkpoint beside the film (docs/checkpoints.md): the identity of the scene (its
// file and every file it references, by size and hash), the isotrace version, and the options that change pixels.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/film/film.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace::cli {

// The options that decide a pixel's value; a resumed render must use the same.
struct PixelOptions {
    int spp = 0;                          // the render's sample target
    RasterSize resolution;
    std::uint64_t seed = 0;
    std::vector<std::string> extra_aovs;  // --aov, by name
    bool reference = false;               // --reference
    std::optional<double> target_error;   // --target-error: decides where the render ends
    std::vector<std::string> settings;    // the scene overrides (LoadedScene::settings)
};

// Writes `film` with its metadata atomically to `path`.
void save_checkpoint(const std::filesystem::path& path, const LoadedScene& scene, const PixelOptions& options,
                     const Film& film);

struct ResumePoint {
    nlohmann::json metadata;
    PixelOptions options;
    std::string film_state;
};

// Reads a checkpoint and its metadata; throws InputError naming the file for anything unusable, including a
// checkpoint written by another isotrace version.
ResumePoint read_resume_point(const std::filesystem::path& path);

// Throws InputError saying which file changed if `scene` (its file and the files it references) is not the scene
// the checkpoint was made from.
void check_same_scene(const ResumePoint& resume, const LoadedScene& scene, const std::string& checkpoint);

}  // namespace isotrace::cli
