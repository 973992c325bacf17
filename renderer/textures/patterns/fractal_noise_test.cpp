#include "renderer/textures/patterns/fractal_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "renderer/textures/patterns/pattern_test_support.h"

namespace isotrace {
namespace {

constexpr NoiseBasis kBases[] = {NoiseBasis::Gradient, NoiseBasis::Simplex};

FractalSettings settings_with(NoiseBasis basis, std::uint32_t seed = 0) {
    FractalSettings settings;
    settings.basis = basis;
    settings.seed = seed;
    return settings;
}

TEST(FractalNoise, FbmHasMeanZeroAndStatedSpread) {
    const auto points = random_points(100000, 100);
    // Octaves of independent noise with amplitudes 1, ½, … add their variances: the spread is the basis's
    // (0.26 gradient, 0.39 simplex) × √(Σ gain^2i) / Σ gain^i = 0.59 of it.
    const double expected_spread[] = {0.155, 0.234};
    for (const NoiseBasis basis : kBases) {
        const FractalOctaves octaves(settings_with(basis));
        const Moments m = moments(points, [&](const Vec3f& p) { return fbm(p, octaves, 0); });
        EXPECT_NEAR(m.mean, 0.0, 0.005);
        EXPECT_NEAR(m.standard_deviation, expected_spread[int(basis)], 0.01);
        EXPECT_GE(m.minimum, -1.0);
        EXPECT_LE(m.maximum, 1.0);
    }
}

TEST(FractalNoise, TurbulenceAndRidgedStayInUnitRange) {
    const auto points = random_points(100000, 100);
    for (const NoiseBasis basis : kBases) {
        const FractalOctaves octaves(settings_with(basis));
        const Moments t = moments(points, [&](const Vec3f& p) { return turbulence(p, octaves, 0); });
        const Moments r = moments(points, [&](const Vec3f& p) { return ridged(p, octaves, 0); });
        EXPECT_GE(t.minimum, 0.0);
        EXPECT_LE(t.maximum, 1.0);
        EXPECT_GE(r.minimum, 0.0);
        EXPECT_LE(r.maximum, 1.0);
        EXPECT_GT(t.standard_deviation, 0.05);  // a field, not a constant
        EXPECT_GT(r.standard_deviation, 0.05);
    }
}

// At footprint 0 nothing fades: fbm is the normalised sum of the octaves, each in its own domain.
TEST(FractalNoise, FootprintZeroIsTheUnfilteredSum) {
    for (const NoiseBasis basis : kBases) {
        const FractalSettings settings = settings_with(basis, 7);
        const FractalOctaves octaves(settings);
        for (const Vec3f& p : random_points(1000, 30)) {
            float sum = 0, total = 0, amplitude = 1, frequency = 1;
            for (int octave = 0; octave < settings.octaves; ++octave) {
                const OctaveDomain domain = octave_turn(settings.seed, octave).domain(p * frequency);
                sum += amplitude * basis_noise(basis, domain.point, domain.seed);
                total += amplitude;
                amplitude *= settings.gain;
                frequency *= settings.lacunarity;
            }
            ASSERT_FLOAT_EQ(fbm(p, octaves, 0), sum / total);
        }
    }
}

// The octaves' turns, taken once, are those the seed and octave hash to, bit for bit, for every octave a fractal can
// have; the settings are clamped as documented.
TEST(FractalNoise, FractalOctavesKeepEveryOctavesTurn) {
    for (const std::uint32_t seed : {0u, 7u, 2147483647u}) {
        const FractalOctaves octaves(FractalSettings{NoiseBasis::Gradient, kMaxFractalOctaves, 1.7f, 0.5f, seed});
        ASSERT_EQ(octaves.count(), kMaxFractalOctaves);
        for (const Vec3f& p : random_points(200, 50)) {
            float frequency = 1;
            for (int octave = 0; octave < octaves.count(); ++octave) {
                const OctaveDomain hashed = octave_turn(seed, octave).domain(p * frequency);
                const OctaveDomain tabled = octaves.turn(octave).domain(p * frequency);
                ASSERT_EQ(std::memcmp(&hashed.point, &tabled.point, sizeof(Vec3f)), 0) << "octave " << octave;
                ASSERT_EQ(hashed.seed, tabled.seed);
                frequency *= octaves.lacunarity();
            }
        }
    }
    const FractalOctaves odd(FractalSettings{NoiseBasis::Gradient, 1000000, std::nanf(""), 100, 1});
    EXPECT_EQ(odd.count(), kMaxFractalOctaves);
    EXPECT_EQ(odd.lacunarity(), 1);
    EXPECT_EQ(odd.gain(), 4);
    EXPECT_EQ(FractalOctaves(FractalSettings{NoiseBasis::Gradient, -3}).count(), 0);
}

// A footprint wider than the lowest octave's wavelength fades every octave to its mean: a constant field.
TEST(FractalNoise, WideFootprintsLeaveNoVariance) {
    const auto points = random_points(10000, 100);
    for (const NoiseBasis basis : kBases) {
        const FractalOctaves octaves(settings_with(basis));
        for (const auto pattern : {&fbm, &turbulence, &ridged}) {
            const Moments m = moments(points, [&](const Vec3f& p) { return pattern(p, octaves, 10); });
            EXPECT_EQ(m.minimum, m.maximum);
        }
    }
}

// Fading replaces an octave by its mean, so the mean over space does not move with the footprint (this also checks
// the measured statistics a faded octave takes), while the spread shrinks. Ridged follows its weights' mean to
// first order only: where every octave has faded, its mean is off by up to 0.015.
TEST(FractalNoise, FootprintKeepsTheMeanAndShrinksTheSpread) {
    const auto points = random_points(100000, 100);
    for (const NoiseBasis basis : kBases) {
        const FractalOctaves octaves(settings_with(basis));
        for (const auto pattern : {&fbm, &turbulence, &ridged}) {
            const Moments sharp = moments(points, [&](const Vec3f& p) { return pattern(p, octaves, 0); });
            const Moments blurred = moments(points, [&](const Vec3f& p) { return pattern(p, octaves, 0.1f); });
            const Moments flat = moments(points, [&](const Vec3f& p) { return pattern(p, octaves, 10); });
            EXPECT_NEAR(blurred.mean, sharp.mean, 0.004);
            EXPECT_NEAR(flat.mean, sharp.mean, pattern == &ridged ? 0.015 : 0.004);
            EXPECT_LT(blurred.standard_deviation, sharp.standard_deviation);
        }
    }
}

// The fade is smooth: as the footprint grows in small steps the value moves in small steps (cutting an octave
// off would jump by that octave's whole contribution).
TEST(FractalNoise, FootprintFadeIsSmooth) {
    for (const NoiseBasis basis : kBases) {
        const FractalOctaves octaves(settings_with(basis, 3));
        for (const Vec3f& p : random_points(20, 10)) {
            for (const auto pattern : {&fbm, &turbulence, &ridged}) {
                const auto at = [&](float footprint) { return pattern(p, octaves, footprint); };
                EXPECT_LT(largest_footprint_step(at, 0.6f), 2e-3f);
            }
        }
    }
}

TEST(FractalNoise, SeedsGiveUncorrelatedFields) {
    const auto points = random_points(50000, 100);
    for (const NoiseBasis basis : kBases) {
        const FractalOctaves a(settings_with(basis, 0)), b(settings_with(basis, 1));
        for (const auto pattern : {&fbm, &turbulence, &ridged}) {
            const double r = correlation(
                points, [&](const Vec3f& p) { return pattern(p, a, 0); },
                [&](const Vec3f& p) { return pattern(p, b, 0); });
            EXPECT_LT(std::abs(r), 0.03);
        }
    }
}

TEST(FractalNoise, AnySettingsGiveFiniteValuesInRange) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN(), kInfinity = std::numeric_limits<float>::infinity();
    const FractalSettings odd[] = {
        {NoiseBasis::Gradient, 0, 2, 0.5f, 1},      {NoiseBasis::Gradient, -3, 2, 0.5f, 1},
        {NoiseBasis::Simplex, 1000000, 2, 0.5f, 1}, {NoiseBasis::Gradient, 8, kNaN, kNaN, 1},
        {NoiseBasis::Simplex, 8, kInfinity, kInfinity, 1}, {NoiseBasis::Gradient, 8, -2, -1, 1},
    };
    for (const FractalSettings& settings : odd) {
        const FractalOctaves octaves(settings);
        for (const float footprint : {0.0f, 0.3f, kNaN, kInfinity, -1.0f}) {
            const Vec3f p{0.3f, -2.7f, 11.1f};
            const float f = fbm(p, octaves, footprint), t = turbulence(p, octaves, footprint),
                        r = ridged(p, octaves, footprint);
            EXPECT_TRUE(std::abs(f) <= 1) << f;
            EXPECT_TRUE(t >= 0 && t <= 1) << t;
            EXPECT_TRUE(r >= 0 && r <= 1) << r;
        }
    }
}

}  // namespace
}  // namespace isotrace
