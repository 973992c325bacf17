#pragma once
// Named attributes of an image file (render settings, statistics, format tags), in the order they were set.
#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace isotrace {

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
