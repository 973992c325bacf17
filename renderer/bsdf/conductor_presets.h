#pragma once
// Complex IORs of common metals as RGB triples, for conductor materials named by element symbol.
#include <optional>
#include <span>
#include <string_view>

#include "renderer/bsdf/fresnel.h"

namespace isotrace {

struct ConductorPreset {
    std::string_view symbol;  // chemical symbol: "Au", "Ag", ...
    ComplexIor ior;
};

std::span<const ConductorPreset> conductor_presets();

// The preset with this symbol (case-sensitive), if any.
std::optional<ComplexIor> find_conductor_preset(std::string_view symbol);

}  // namespace isotrace
