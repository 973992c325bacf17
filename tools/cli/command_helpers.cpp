#include "tools/cli/command_helpers.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <stdexcept>

#include "renderer/core/atomic_file.h"
#include "renderer/core/input_error.h"
#include "renderer/core/memory_budget.h"

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

std::uint64_t parse_seed(const std::string& text, const std::string& option) {
    std::uint64_t seed = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seed);
    const bool digits_only = !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) {
        return std::isdigit(c);
    });
    if (!digits_only || error != std::errc() || end != text.data() + text.size())
        throw InputError({}, option,
                         "expected a whole number from 0 to 18446744073709551615, got \"" + text + "\"");
    return seed;
}

double parse_positive_number(const std::string& text, const std::string& option, const std::string& what) {
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
        !(value > 0))
        throw InputError({}, option, "expected " + what + " > 0, got \"" + text + "\"");
    return value;
}

double parse_seconds(const std::string& text, const std::string& option) {
    return parse_positive_number(text, option, "a number of seconds");
}

std::uint64_t parse_memory_size(const std::string& text, const std::string& option) {
    static const std::regex pattern(R"(([0-9]+(\.[0-9]+)?) *([kKmMgGtT%]?)[bB]?)");
    std::smatch match;
    const auto bad = [&](const std::string& why) {
        return InputError({}, option, why + ", got \"" + text + "\" (examples: 16G, 512M, 50%)");
    };
    if (!std::regex_match(text, match, pattern)) throw bad("expected a size with K, M, G or T, or a percentage");
    const double number = std::stod(match[1]);
    const char unit = char(std::toupper(static_cast<unsigned char>(match[3].str().empty() ? ' ' : match[3].str()[0])));
    double bytes = number;
    if (unit == '%') {
        if (number > 100) throw bad("a percentage of physical memory must be at most 100");
        bytes = double(MemoryBudget::physical_memory_bytes()) * number / 100;
    } else {
        const std::string units = " KMGT";
        bytes = std::ldexp(number, 10 * int(units.find(unit)));
    }
    if (!(bytes >= double(1 << 20))) throw bad("the limit must be at least 1M");
    if (bytes >= 1.8e19) throw bad("the limit is too large");
    return std::uint64_t(bytes);
}

void require_extension(const std::string& path, const std::string& extension, const std::string& option) {
    std::string actual = std::filesystem::path(path).extension().string();
    for (char& c : actual) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (actual != extension) throw InputError({}, option, "\"" + path + "\" must end in " + extension);
}

std::vector<NamedPath> scene_inputs(const LoadedScene& scene) {
    std::vector<NamedPath> inputs{{scene.path, "the scene"}};
    for (const auto& file : scene.referenced_files) inputs.push_back({file.string(), "a file the scene reads"});
    return inputs;
}

void write_text_output(const std::string& path, const std::string& text) {
    if (path != kStandardOutput) {
        write_file_atomically(path, text);
        return;
    }
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
        throw std::runtime_error("cannot write to standard output");
}

}  // namespace isotrace::cli
