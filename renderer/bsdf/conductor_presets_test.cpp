#include "renderer/bsdf/conductor_presets.h"

#include <gtest/gtest.h>

#include <set>

namespace isotrace {
namespace {

TEST(ConductorPresets, CoverTheCommonMetalsOnce) {
    std::set<std::string_view> symbols;
    for (const ConductorPreset& preset : conductor_presets()) {
        EXPECT_TRUE(symbols.insert(preset.symbol).second) << preset.symbol;
        EXPECT_TRUE(find_conductor_preset(preset.symbol).has_value());
    }
    for (std::string_view symbol : {"Au", "Ag", "Cu", "Al", "Cr", "Fe", "Ti", "Ni", "Pt", "W"}) {
        EXPECT_TRUE(symbols.contains(symbol)) << symbol;
    }
    EXPECT_FALSE(find_conductor_preset("Unobtainium").has_value());
}

TEST(ConductorPresets, ReflectancesArePhysical) {
    for (const ConductorPreset& preset : conductor_presets()) {
        for (float cos_theta : {1.0f, 0.5f, 0.1f}) {
            const Rgb f = fresnel_conductor(cos_theta, preset.ior);
            EXPECT_TRUE(f.r > 0.3f && f.g > 0.3f && f.b > 0.3f && f.max() < 1.0f) << preset.symbol;
        }
    }
}

TEST(ConductorPresets, GoldMatchesAnIndependentMeasurement) {
    // Normal-incidence reflectance from S. Babar, J. H. Weaver, Appl. Opt. 54, 477 (2015) (refractiveindex.info,
    // Au/nk/Babar.yml, interpolated): 0.967 / 0.842 / 0.363 at 650 / 550 / 450 nm. Measurements of gold differ by
    // a few percent near its absorption edge (500 nm), hence the tolerance.
    const Rgb gold = fresnel_conductor(1.0f, *find_conductor_preset("Au"));
    EXPECT_NEAR(gold.r, 0.967f, 0.02f);
    EXPECT_NEAR(gold.g, 0.842f, 0.06f);
    EXPECT_NEAR(gold.b, 0.363f, 0.06f);
    EXPECT_GT(gold.r, gold.g);  // yellow: red reflected most, blue least
    EXPECT_GT(gold.g, gold.b);
}

}  // namespace
}  // namespace isotrace
