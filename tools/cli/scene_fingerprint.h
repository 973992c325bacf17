#pragma once
// The identity of a scene as files on disk: the scene file and every file it references, by size and FNV-1a
// hash. Checkpoints keep the list to refuse a changed scene; reference images and `isotrace info` carry the
// one-line scene hash made from it.
#include <string>

#include <nlohmann/json.hpp>

#include "renderer/scene/loaded_scene.h"

namespace isotrace::cli {

// [{"path", "bytes", "fnv1a64"}, ...]: the scene file first, then the files it references in sorted order.
// Throws std::runtime_error if a file cannot be read.
nlohmann::json scene_files(const LoadedScene& scene);

// 16 hex digits: FNV-1a 64 of "<bytes> <fnv1a64>\n" for each entry of scene_files, then "set PATH=VALUE\n" for each
// override of LoadedScene::settings. Paths are left out, so the hash is the same for a copy of the scene anywhere.
std::string scene_hash(const LoadedScene& scene);

}  // namespace isotrace::cli
