#pragma once
// Named attributes of an image file (render settings, statistics, format tags), in the order they were set.
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace isotrace {

// How an integer entry is stored: image formats (EXR first) have 32-bit integer attributes, so a larger value is
// written as text rather than wrapped. Both image modules store integers this way.
inline std::variant<int, std::string> integer_attribute(std::int64_t value) {
    if (value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max()) return int(value);
    return std::to_string(value);
}

struct ImageMetadata {
    using Value = std::variant<std::string, double, std::int64_t, std::vector<float>>;
    std::vector<std::pair<std::string, Value>> entries;
    void set(const std::string& name, Value value) {
        entries.emplace_back(name, std::move(value));
    }
    // The first entry called `name` (file formats keep one per name), or nullptr.
    const Value* find(const std::string& name) const {
        for (const auto& [entry, value] : entries)
            if (entry == name) return &value;
        return nullptr;
    }
};

}  // namespace isotrace
