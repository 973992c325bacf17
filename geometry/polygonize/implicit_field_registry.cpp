#include "geometry/polygonize/implicit_field_registry.h"

#include <map>
#include <stdexcept>

namespace isotrace {
namespace {

std::map<std::string, ImplicitFieldFactory>& factories() {
    static std::map<std::string, ImplicitFieldFactory> registered;
    return registered;
}

}  // namespace

void register_implicit_field(const std::string& shape_type, ImplicitFieldFactory factory) {
    // Two factories for one type is a programming error: the second would silently shadow the first.
    if (!factories().emplace(shape_type, std::move(factory)).second)
        throw std::logic_error("implicit field for \"" + shape_type + "\" is registered twice");
}

std::unique_ptr<ImplicitField> implicit_field_of(const Shape& shape) {
    const auto found = factories().find(shape.type_name());
    return found == factories().end() ? nullptr : found->second(shape);
}

std::vector<std::string> implicit_shape_types() {
    std::vector<std::string> types;
    for (const auto& [type, factory] : factories()) types.push_back(type);
    return types;
}

}  // namespace isotrace
