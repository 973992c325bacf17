#include "renderer/scene/scene_settings.h"

#include <algorithm>
#include <cstring>
#include <optional>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/memory_budget.h"

namespace isotrace {

namespace {

constexpr const char* kSetOption = "--set ";
constexpr std::size_t kListedNames = 20;  // names listed in a message; a scene may have millions

[[noreturn]] void fail_at(const SceneSetting& setting, int column, const std::string& problem) {
    throw InputError({setting.origin, column > 0 ? 1 : 0, column}, "", problem);
}

// "a, b, c" (the first kListedNames).
std::string name_list(const std::vector<std::string>& names) {
    std::string list;
    for (std::size_t i = 0; i < std::min(names.size(), kListedNames); ++i) list += (i ? ", " : "") + names[i];
    if (names.size() > kListedNames) list += ", ... (" + std::to_string(names.size()) + " in all)";
    return list;
}

struct Key {
    std::string name;
    int column = 0;  // in the setting's origin; 0 for a shortcut
};

std::vector<Key> split_path(const SceneSetting& setting) {
    if (setting.path.size() > kMaxSettingPathBytes)
        fail_at(setting, setting.path_column,
                "the path is longer than " + std::to_string(kMaxSettingPathBytes) + " characters");
    std::vector<Key> keys;
    for (std::size_t start = 0;;) {
        const std::size_t dot = setting.path.find('.', start);
        const int column = setting.path_column > 0 ? setting.path_column + int(start) : 0;
        std::string name = setting.path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
        if (name.empty())
            fail_at(setting, column,
                    "empty key in the path \"" + setting.path + "\" (keys are separated by single dots)");
        if (keys.size() == kMaxSettingPathKeys)
            fail_at(setting, setting.path_column,
                    "the path has more than " + std::to_string(kMaxSettingPathKeys) + " keys");
        keys.push_back({std::move(name), column});
        if (dot == std::string::npos) return keys;
        start = dot + 1;
    }
}

// The value and everything in it are located in the setting: its origin, at the value's column.
void locate_in(JsonValue& value, const SceneSetting& setting) {
    SourceLocation& where = value.location;
    where.file = setting.origin;
    if (setting.value_column == 0) where.line = where.column = 0;
    else if (where.line == 1) where.column += setting.value_column - 1;
    for (JsonValue& item : value.items) locate_in(item, setting);
    for (auto& member : value.members) locate_in(member.second, setting);
}

JsonValue parse_value(const SceneSetting& setting, MemoryBudget* memory) {
    if (setting.value.size() > kMaxSettingValueBytes)
        fail_at(setting, setting.value_column,
                "the value is longer than " + std::to_string(kMaxSettingValueBytes) + " bytes");
    JsonValue value;
    try {
        value = parse_json(setting.value, setting.origin);  // charged below: a memory error is no syntax error
    } catch (const InputError& error) {
        const std::size_t first = setting.value.find_first_not_of(" \t");
        // Text that starts like an array, object or string was meant as JSON; any other is a bare word.
        if (first != std::string::npos && std::strchr("[{\"", setting.value[first])) {
            JsonValue located;
            located.location = error.location();
            locate_in(located, setting);
            std::string problem = error.problem();  // the parser speaks of files
            const std::size_t ended = problem.find("the file ended");
            if (ended != std::string::npos) problem.replace(ended, 14, "the value ended");
            throw InputError(located.location, setting.path, problem);
        }
        value = JsonValue();
        value.kind = JsonValue::Kind::String;
        value.string = setting.value;
        value.location = {setting.origin, 1, 1};
    }
    locate_in(value, setting);
    if (memory)
        memory->charge(setting.value.size() + JsonValue::tree_bytes(value.tree_size()), "the value of " + setting.origin,
                       value.location, setting.path);
    return value;
}

std::string child_path(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

std::string described(const std::string& path) { return path.empty() ? "the scene" : "\"" + path + "\""; }

// The element of `array` that `key` names: by index, or by its "name" member.
std::size_t element_index(const JsonValue& array, const Key& key, const std::string& path, const SceneSetting& setting) {
    if (!key.name.empty() && key.name.size() <= 9 &&
        std::all_of(key.name.begin(), key.name.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        const std::size_t index = std::stoul(key.name);
        if (index >= array.items.size())
            fail_at(setting, key.column,
                    "no element " + key.name + " in " + described(path) + ", which has " +
                        std::to_string(array.items.size()) + " element(s)");
        return index;
    }
    std::vector<std::string> names;
    std::optional<std::size_t> found;
    for (std::size_t i = 0; i < array.items.size(); ++i) {
        const JsonValue* name = array.items[i].is_object() ? array.items[i].find("name") : nullptr;
        if (!name || !name->is_string()) continue;
        names.push_back(name->string);
        if (name->string != key.name) continue;
        if (found)
            fail_at(setting, key.column,
                    "several elements of " + described(path) + " are named \"" + key.name + "\": use an index");
        found = i;
    }
    if (!found)
        fail_at(setting, key.column,
                "no element of " + described(path) + " is named \"" + key.name + "\"" + did_you_mean(key.name, names) +
                    (names.empty() ? "; its elements have no \"name\": use an index"
                                   : "; names: " + name_list(names) + " (or use an index)"));
    return *found;
}

void apply(JsonValue& document, const SceneSetting& setting, MemoryBudget* memory) {
    const std::vector<Key> keys = split_path(setting);
    JsonValue value = parse_value(setting, memory);
    JsonValue* node = &document;
    std::string path;  // as the loader names it: objects[2].shape
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const Key& key = keys[i];
        const bool last = i + 1 == keys.size();
        JsonValue* child = nullptr;
        std::string child_name;
        if (node->is_object()) {
            child = node->find(key.name);
            child_name = child_path(path, key.name);
            std::vector<std::string> names;
            std::string suggestion;
            if (!child) {
                for (const auto& member : node->members) names.push_back(member.first);
                suggestion = did_you_mean(key.name, names);
            }
            // A missing section is created (scenes leave optional ones out), unless the key looks like a typo of
            // one that is there; the loader then checks the new keys like the file's own.
            if (!child && (last || setting.create_sections || suggestion.empty())) {
                JsonValue section;
                section.kind = JsonValue::Kind::Object;
                section.location = value.location;
                node->members.emplace_back(key.name, last ? std::move(value) : std::move(section));
                node->reindex();
                child = &node->members.back().second;
                if (last) return;
            }
            if (!child) {
                fail_at(setting, key.column,
                        "no key \"" + key.name + "\" in " + described(path) + suggestion +
                            (names.empty() ? "" : "; keys there: " + name_list(names)));
            }
        } else if (node->is_array()) {
            const std::size_t index = element_index(*node, key, path, setting);
            child = &node->items[index];
            child_name = path + "[" + std::to_string(index) + "]";
        } else {
            fail_at(setting, key.column,
                    described(path) + " is a " + JsonValue::kind_name(node->kind) + ", which has no \"" + key.name +
                        "\" in it");
        }
        if (last) {
            *child = std::move(value);
            return;
        }
        node = child;
        path = std::move(child_name);
    }
}

}  // namespace

SceneSetting parse_scene_setting(const std::string& argument) {
    SceneSetting setting;
    setting.origin = kSetOption + argument;
    const std::size_t equals = argument.find('=');
    if (equals == std::string::npos)
        throw InputError({}, "--set", "expected PATH=VALUE (for example film.spp=64), got \"" + argument + "\"");
    setting.path = argument.substr(0, equals);
    setting.value = argument.substr(equals + 1);
    setting.path_column = int(std::strlen(kSetOption)) + 1;
    setting.value_column = setting.path_column + int(equals) + 1;
    return setting;
}

SceneSetting shortcut_setting(std::string path, std::string value, std::string origin) {
    SceneSetting setting;
    setting.path = std::move(path);
    setting.value = std::move(value);
    setting.origin = std::move(origin);
    setting.create_sections = true;
    return setting;
}

namespace {

SceneSetting render_option(std::string path, std::string value, std::string origin) {
    SceneSetting setting = shortcut_setting(std::move(path), std::move(value), std::move(origin));
    setting.recorded_apart = true;
    return setting;
}

}  // namespace

SceneSetting spp_setting(int spp) {
    return render_option("film.spp", std::to_string(spp), "--spp " + std::to_string(spp));
}

SceneSetting resolution_setting(RasterSize size) {
    const std::string w = std::to_string(size.width), h = std::to_string(size.height);
    return render_option("film.resolution", "[" + w + ", " + h + "]", "--res " + w + "x" + h);
}

SceneSetting seed_setting(std::uint64_t seed) {
    return render_option("sampler.seed", std::to_string(seed), "--seed " + std::to_string(seed));
}

void apply_scene_settings(JsonValue& document, const std::vector<SceneSetting>& settings, MemoryBudget* memory) {
    if (settings.size() > kMaxSettings)
        throw InputError({}, "--set", "more than " + std::to_string(kMaxSettings) + " overrides");
    for (const SceneSetting& setting : settings) apply(document, setting, memory);
}

}  // namespace isotrace
