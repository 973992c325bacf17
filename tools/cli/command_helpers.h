#pragma once
// Argument checks and output writing shared by the sub-commands.
#include <cstdint>
#include <string>

#include "renderer/plugin/camera.h"

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

// Rejects an output path that cannot be written before any work is done (it would otherwise fail only after the
// render, with exit code 1): its directory is missing or unwritable, or the path is a directory.
void check_output_directory(const std::string& path, const std::string& option);

// Both checks before any work: the path ends in `extension` (".png"; any letter case) and its directory exists.
void check_output_file(const std::string& path, const std::string& extension, const std::string& option);

// Writes a text file atomically (see renderer/core/atomic_file.h).
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace isotrace::cli
