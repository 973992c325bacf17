#pragma once
// Scene files that include others: a top-level "include" (a file name or a list of them, relative to the including
// file) merges those files' scene sections into the including file (docs/scene-authoring.md).
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "renderer/params/json_document.h"

namespace isotrace {

class MemoryBudget;

// Bounds on what one scene may include: nesting depth and the number of included files (a file included twice counts
// twice). Together with the scene file they may hold at most the scene-size limit.
constexpr int kMaxIncludeDepth = 16;
constexpr int kMaxIncludedFiles = 256;

struct SceneDocument {
    JsonValue root;  // the scene file with its includes merged in and its "include" removed
    // Each included file's directory (absolute), by the name its values' locations carry.
    std::map<std::string, std::filesystem::path> included_directories;
    std::vector<std::filesystem::path> included_files;  // absolute
};

// Reads the scene file at `path` and every file it includes, merged. Throws InputError for a file that is missing,
// not JSON or not an object, for an include cycle and past the bounds, at the position of the include that names it.
SceneDocument read_scene_document(const std::string& path, std::uint64_t max_bytes, MemoryBudget* memory);

// Merges the scene sections of `overlay` into `base` (two objects): the lists of the top level ("lights", "objects")
// are concatenated, base's items first; objects merge key by key, recursively; any other value (an array inside a
// section is a value, such as a colour), or two values of different kinds, is replaced by overlay's.
void merge_scene_sections(JsonValue& base, JsonValue&& overlay);

}  // namespace isotrace
