#include "renderer/bsdf/conductor_presets.h"

#include <algorithm>
#include <array>

namespace isotrace {
namespace {

// (eta, k) at 650 / 550 / 450 nm for the R / G / B channels (single wavelengths, not averages over the
// channels' spectral responses), linearly interpolated between the tabulated wavelengths of the measured data
// in the refractiveindex.info database (https://github.com/polyanskiy/refractiveindex.info-database, CC0):
//   Au, Ag, Cu:     P. B. Johnson, R. W. Christy, Phys. Rev. B 6, 4370 (1972)       data/main/<X>/nk/Johnson.yml
//   Cr, Fe, Ti, Ni: P. B. Johnson, R. W. Christy, Phys. Rev. B 9, 5056 (1974)       data/main/<X>/nk/Johnson.yml
//   Al:             A. D. Rakic, Appl. Opt. 34, 4755 (1995)                          data/main/Al/nk/Rakic.yml
//   Pt:             A. D. Rakic et al., Appl. Opt. 37, 5271 (1998), Lorentz-Drude fit data/main/Pt/nk/Rakic-LD.yml
//   W:              J. H. Weaver, C. G. Olson, D. W. Lynch, Phys. Rev. B 12, 1293 (1975) data/main/W/nk/Weaver.yml
constexpr std::array kPresets{
    ConductorPreset{"Au", {{0.156f, 0.424f, 1.383f}, {3.602f, 2.472f, 1.915f}}},
    ConductorPreset{"Ag", {{0.052f, 0.060f, 0.040f}, {4.409f, 3.597f, 2.648f}}},
    ConductorPreset{"Cu", {{0.238f, 1.007f, 1.240f}, {3.626f, 2.582f, 2.393f}}},
    ConductorPreset{"Al", {{1.558f, 1.015f, 0.633f}, {7.712f, 6.627f, 5.454f}}},
    ConductorPreset{"Cr", {{3.107f, 3.181f, 2.323f}, {3.331f, 3.329f, 3.135f}}},
    ConductorPreset{"Fe", {{2.911f, 2.950f, 2.584f}, {3.089f, 2.932f, 2.767f}}},
    ConductorPreset{"Ti", {{2.741f, 2.542f, 2.267f}, {3.814f, 3.435f, 3.038f}}},
    ConductorPreset{"Ni", {{1.990f, 1.921f, 1.729f}, {4.209f, 3.616f, 2.944f}}},
    ConductorPreset{"Pt", {{2.370f, 2.091f, 1.851f}, {4.254f, 3.704f, 3.140f}}},
    ConductorPreset{"W", {{3.671f, 3.522f, 3.315f}, {2.932f, 2.741f, 2.516f}}},
};

}  // namespace

std::span<const ConductorPreset> conductor_presets() {
    return kPresets;
}

std::optional<ComplexIor> find_conductor_preset(std::string_view symbol) {
    const auto it = std::ranges::find(kPresets, symbol, &ConductorPreset::symbol);
    if (it == kPresets.end()) return std::nullopt;
    return it->ior;
}

}  // namespace isotrace
