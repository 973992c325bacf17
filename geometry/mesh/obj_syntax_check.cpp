#include "geometry/mesh/obj_syntax_check.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

std::vector<std::string_view> words_of(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

bool is_finite_number(std::string_view word) {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);  // from_chars does not take a leading '+'
    double value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    return !word.empty() && error == std::errc() && end == word.data() + word.size() && std::isfinite(value);
}

// One OBJ index: a whole number, negative (relative) or positive, never 0, within int.
bool is_index(std::string_view word) {
    long long value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    return !word.empty() && error == std::errc() && end == word.data() + word.size() && value != 0 &&
           value > std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max();
}

// "v", "v/vt", "v//vn" or "v/vt/vn": the position index is required, the others may be empty.
bool is_face_corner(std::string_view word) {
    int part = 0;
    for (;;) {
        const std::size_t slash = word.find('/');
        const std::string_view index = word.substr(0, slash);
        if (!(is_index(index) || (part > 0 && index.empty()))) return false;
        if (slash == std::string_view::npos) return true;
        if (++part > 2) return false;
        word.remove_prefix(slash + 1);
    }
}

}  // namespace

void check_obj_syntax(std::string_view text, const std::string& path) {
    int line_number = 0;
    while (!text.empty()) {
        ++line_number;
        const std::size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
        const std::vector<std::string_view> words = words_of(line.substr(0, line.find('#')));
        if (words.empty()) continue;
        const std::string_view keyword = words[0];
        const auto fail = [&](const std::string& problem) {
            throw InputError({path, line_number}, "", std::string(keyword) + " line: " + problem);
        };
        std::size_t minimum = 0;
        bool numbers = false, indices = false;
        if (keyword == "v" || keyword == "vn") minimum = 3, numbers = true;
        else if (keyword == "vt") minimum = 1, numbers = true;
        else if (keyword == "f") minimum = 3, indices = true;
        else if (keyword == "l") minimum = 2, indices = true;
        else if (keyword == "p") minimum = 1, indices = true;
        if (words.size() - 1 < minimum)
            fail("expected at least " + std::to_string(minimum) + " values, found " + std::to_string(words.size() - 1));
        for (std::size_t i = 1; i < words.size(); ++i) {
            if (numbers && !is_finite_number(words[i]))
                fail("\"" + std::string(words[i]) + "\" is not a finite number");
            if (indices && !is_face_corner(words[i]))
                fail("\"" + std::string(words[i]) +
                     "\" is not a valid index (whole numbers from 1, or negative, within 32 bits; v, v/vt, v//vn or v/vt/vn)");
        }
    }
}

}  // namespace isotrace
