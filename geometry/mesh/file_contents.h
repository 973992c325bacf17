#pragma once
// Reads a whole mesh file into memory, so every loader reports a missing or unreadable file the same way.
#include <string>

namespace isotrace {

// Throws InputError naming `path` if the file cannot be opened or read.
std::string read_file_contents(const std::string& path);

}  // namespace isotrace
