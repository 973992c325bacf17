#pragma once
// A file name's extension in lower case (".EXR" → ".exr"), which output formats are chosen by.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace isotrace {

inline std::string lower_extension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

}  // namespace isotrace
