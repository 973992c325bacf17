#pragma once
// Argument checks and output writing shared by the sub-commands.
#include <string>

#include "renderer/plugin/camera.h"

namespace isotrace::cli {

// "WIDTHxHEIGHT" (each side 1..65536); throws InputError naming `option` otherwise.
RasterSize parse_resolution(const std::string& text, const std::string& option);

// Rejects an output path whose directory does not exist before any work is done (it would otherwise fail only
// after the render, with exit code 1).
void check_output_directory(const std::string& path, const std::string& option);

// Both checks before any work: the path ends in `extension` (".png"; any letter case) and its directory exists.
void check_output_file(const std::string& path, const std::string& extension, const std::string& option);

// Writes a text file atomically (see renderer/core/atomic_file.h).
void write_text_atomically(const std::string& path, const std::string& text);

}  // namespace isotrace::cli
