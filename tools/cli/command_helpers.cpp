#include "tools/cli/command_helpers.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>

#include "renderer/core/atomic_file.h"
#include "renderer/core/input_error.h"

namespace isotrace::cli {

RasterSize parse_resolution(const std::string& text, const std::string& option) {
    static const std::regex pattern(R"((\d{1,5})[xX](\d{1,5}))");
    std::smatch match;
    if (!std::regex_match(text, match, pattern))
        throw InputError({}, option, "expected WIDTHxHEIGHT (for example 640x480), got \"" + text + "\"");
    const RasterSize size{std::stoi(match[1]), std::stoi(match[2])};
    if (size.width < 1 || size.height < 1 || size.width > 65536 || size.height > 65536)
        throw InputError({}, option, "each side must be between 1 and 65536 pixels");
    return size;
}

void check_output_directory(const std::string& path, const std::string& option) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code error;
    if (!parent.empty() && !std::filesystem::is_directory(parent, error))
        throw InputError({}, option, "the directory \"" + parent.string() + "\" of \"" + path + "\" does not exist");
}

void check_output_file(const std::string& path, const std::string& extension, const std::string& option) {
    std::string actual = std::filesystem::path(path).extension().string();
    for (char& c : actual) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (actual != extension) throw InputError({}, option, "\"" + path + "\" must end in " + extension);
    check_output_directory(path, option);
}

void write_text_atomically(const std::string& path, const std::string& text) {
    write_atomically(path, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary);
        out << text;
        if (!out.flush()) throw std::runtime_error("cannot write " + path);
    });
}

}  // namespace isotrace::cli
