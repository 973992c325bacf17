#include "tools/cli/scene_fingerprint.h"

#include <cstdio>
#include <stdexcept>

#include "renderer/core/fnv_hash.h"
#include "renderer/core/input_file.h"

namespace isotrace::cli {
namespace {

nlohmann::json fingerprint(const std::filesystem::path& file) {
    const std::string bytes = read_input_file(file, UINT64_MAX, "");
    return {{"path", file.string()}, {"bytes", bytes.size()}, {"fnv1a64", hex64(fnv1a_64(bytes))}};
}

}  // namespace

nlohmann::json scene_files(const LoadedScene& scene) {
    nlohmann::json files = nlohmann::json::array({fingerprint(scene.path)});
    for (const auto& file : scene.referenced_files) files.push_back(fingerprint(file));
    return files;
}

std::string scene_hash(const LoadedScene& scene) {
    std::string lines;
    for (const nlohmann::json& file : scene_files(scene))
        lines += std::to_string(file.at("bytes").get<std::uint64_t>()) + " " + file.at("fnv1a64").get<std::string>() + "\n";
    // The scene's overrides change it as its files do; a scene without them keeps the hash it always had.
    for (const std::string& setting : scene.settings) lines += "set " + setting + "\n";
    return hex64(fnv1a_64(lines));
}

}  // namespace isotrace::cli
