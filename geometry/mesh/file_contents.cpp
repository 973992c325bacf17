#include "geometry/mesh/file_contents.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include "renderer/core/input_error.h"

namespace isotrace {

std::string read_file_contents(const std::string& path) {
    // A directory opens fine on Linux and then reads as empty, which would give a misleading message.
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored)) throw InputError({path}, "", "is a directory, not a file");
    std::ifstream stream(path, std::ios::binary);
    if (!stream) throw InputError({path}, "", "cannot open file");
    std::string contents{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
    if (stream.bad()) throw InputError({path}, "", "cannot read file");
    return contents;
}

}  // namespace isotrace
