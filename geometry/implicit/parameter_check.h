#pragma once
// One wording for every rejected implicit-surface parameter, so that the scene layer can prefix the element
// index and the user reads "radius: must be finite and >= 0 (got -1)".
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "renderer/math/vec3.h"

namespace isotrace {

// Throws std::invalid_argument "<field>: <requirement> (got <value>)" unless `holds`.
inline void require_parameter(bool holds, std::string_view field, std::string_view requirement, double value) {
    if (holds) return;
    std::ostringstream message;
    message << field << ": " << requirement << " (got " << value << ")";
    throw std::invalid_argument(message.str());
}

// The same for every component of a vector, reporting the first that fails.
template <class Predicate>
void require_components(const Vec3d& v, Predicate holds, std::string_view field, std::string_view requirement) {
    for (int k = 0; k < 3; ++k) require_parameter(holds(v[k]), field, requirement, v[k]);
}

}  // namespace isotrace
