#include "renderer/scene/named_values.h"

#include <algorithm>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/memory_budget.h"

namespace isotrace {
namespace {

const std::string kSectionName = "values";
constexpr const char* kReference = "$value";

class Substitution {
public:
    Substitution(const JsonValue& values, MemoryBudget& memory) : values_(values), memory_(memory) {
        for (const auto& member : values.members) names_.push_back(member.first);
    }

    void visit(JsonValue& value) {
        if (is_reference(value)) {
            replace(value);
            return;
        }
        for_each_child(value, [this](JsonValue& child) { visit(child); });
    }

    // Throws at the first reference inside a named value: values do not refer to each other.
    void check_definitions() {
        path_.push_back({&kSectionName, 0});
        check_no_reference(values_);
        path_.pop_back();
    }

private:
    void check_no_reference(const JsonValue& value) {
        if (is_reference(value))
            throw InputError(value.location, current_path(), "a named value cannot refer to another named value");
        for_each_child(value, [this](const JsonValue& child) { check_no_reference(child); });
    }

    // Calls `action` on every item or member of `value` with the path extended to it.
    template <class Value, class Action>
    void for_each_child(Value& value, Action&& action) {
        for (std::size_t i = 0; i < value.items.size(); ++i) {
            path_.push_back({nullptr, i});
            action(value.items[i]);
            path_.pop_back();
        }
        for (auto& [key, member] : value.members) {
            path_.push_back({&key, 0});
            action(member);
            path_.pop_back();
        }
    }

    struct Segment {
        const std::string* key;  // null for an array element
        std::size_t index;
    };

    static bool is_reference(const JsonValue& value) { return value.is_object() && value.find(kReference); }

    // The JSON path of the value visited, as the loader writes it: objects[2].material (built only for messages).
    std::string current_path() const {
        std::string path;
        for (const Segment& segment : path_)
            path += segment.key ? (path.empty() ? "" : ".") + *segment.key : "[" + std::to_string(segment.index) + "]";
        return path;
    }

    void replace(JsonValue& reference) {
        const std::string path = current_path();
        const JsonValue& name = *reference.find(kReference);
        if (reference.members.size() != 1 || !name.is_string())
            throw InputError(reference.location, path,
                             "a reference to a named value is {\"$value\": \"NAME\"}, with nothing else in the object");
        const JsonValue* value = values_.find(name.string);
        if (!value) {
            std::string known;
            for (const std::string& n : names_) known += (known.empty() ? "" : ", ") + n;
            throw InputError(name.location, path,
                             "unknown value \"" + name.string + "\"" + did_you_mean(name.string, names_) +
                                 (known.empty() ? "; the scene defines no \"values\"" : "; defined: " + known));
        }
        memory_.charge(JsonValue::tree_bytes(value->tree_size()), "a copy of the value \"" + name.string + "\"",
                       name.location, path);
        reference = *value;  // with the location of its definition, where its text is
    }

    const JsonValue& values_;
    MemoryBudget& memory_;
    std::vector<std::string> names_;
    std::vector<Segment> path_;
};

}  // namespace

void substitute_named_values(JsonValue& document, MemoryBudget& memory) {
    if (!document.is_object()) return;
    JsonValue values;
    values.kind = JsonValue::Kind::Object;
    const auto section = std::find_if(document.members.begin(), document.members.end(),
                                      [](const auto& member) { return member.first == kSectionName; });
    if (section != document.members.end()) {
        if (!section->second.is_object())
            throw InputError(section->second.location, kSectionName,
                             std::string("expected an object of named values, found ") +
                                 JsonValue::kind_name(section->second.kind));
        values = std::move(section->second);
        document.members.erase(section);
        document.reindex();
    }
    Substitution substitution(values, memory);
    substitution.check_definitions();
    substitution.visit(document);
}

}  // namespace isotrace
