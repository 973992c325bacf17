#pragma once
// Argument checks and output writing shared by the sub-commands.
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/core/output_paths.h"
#include "renderer/plugin/camera.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace::cli {

// "WIDTHxHEIGHT" (each side 1..65536); throws InputError naming `option` otherwise.
RasterSize parse_resolution(const std::string& text, const std::string& option);

// A seed: a whole number in [0, 2^64 - 1], decimal digits only ("-1" is not 2^64 - 1, "2^64" is not clamped).
std::uint64_t parse_seed(const std::string& text, const std::string& option);

// A finite number > 0 (no nan, inf, 0 or negative values); the error names `option` and says `what` was expected.
double parse_positive_number(const std::string& text, const std::string& option, const std::string& what);

// Seconds: parse_positive_number for a number of seconds.
double parse_seconds(const std::string& text, const std::string& option);

// A memory size: bytes with an optional K, M, G or T suffix (powers of 1024), or a percentage of physical memory
// ("50%"). At least 1 MiB.
std::uint64_t parse_memory_size(const std::string& text, const std::string& option);

// The path ends in `extension` (".png"; any letter case); throws InputError naming `option` otherwise.
void require_extension(const std::string& path, const std::string& extension, const std::string& option);

// The scene file and every file it names, as inputs that no output may replace.
std::vector<NamedPath> scene_inputs(const LoadedScene& scene);

// Writes a text output: atomically (see renderer/core/atomic_file.h), or to standard output for "-".
void write_text_output(const std::string& path, const std::string& text);

}  // namespace isotrace::cli
