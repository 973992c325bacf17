#pragma once
// A closed set of names for an enum's values, written once as a table: the choices a parser accepts, the value a
// name stands for, the name printed back and the lists in help texts all come from it.
#include <stdexcept>
#include <string>
#include <vector>

namespace isotrace {

template <class Enum>
struct EnumName {
    Enum value;
    const char* name;
};

// The names, in the table's order.
template <class Table>
std::vector<std::string> enum_names(const Table& table) {
    std::vector<std::string> names;
    for (const auto& entry : table) names.emplace_back(entry.name);
    return names;
}

// The value `name` stands for. The caller has checked the name against enum_names(table) (SceneNode::choice_or
// does): a name the table lacks is a programming error.
template <class Table>
auto enum_value(const Table& table, const std::string& name) {
    for (const auto& entry : table)
        if (name == entry.name) return entry.value;
    throw std::logic_error("no value is named \"" + name + "\"");
}

// The name of `value`; every value of the enum is in the table.
template <class Table, class Enum>
const char* enum_name(const Table& table, Enum value) {
    for (const auto& entry : table)
        if (entry.value == value) return entry.name;
    throw std::logic_error("a value without a name");
}

}  // namespace isotrace
