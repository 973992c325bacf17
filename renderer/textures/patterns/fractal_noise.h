#pragma once
// Fractal sums of noise octaves (Musgrave, "Texturing & Modeling: A Procedural Approach"): fBm, turbulence and the
// ridged multifractal, band-limited by fading out the octaves a pixel footprint cannot resolve.
#include <cstdint>
#include <vector>

#include "renderer/math/vec3.h"

namespace isotrace {

enum class NoiseBasis { Gradient, Simplex };

// Octave i has frequency lacunarity^i and amplitude gain^i; each octave has its own seed, derived from `seed`.
// So that any settings give a finite value, octaves is clamped to [0, kMaxFractalOctaves], lacunarity to
// [1, 16] and gain to [0, 4] (NaN to the lower bound).
struct FractalSettings {
    NoiseBasis basis = NoiseBasis::Gradient;
    int octaves = 5;
    float lacunarity = 2;
    float gain = 0.5f;
    std::uint32_t seed = 0;
};

constexpr int kMaxFractalOctaves = 24;

// Where an octave samples its noise: the point and the seed of that octave's noise.
struct OctaveDomain {
    Vec3f point;
    std::uint32_t seed;
};

// Octave `octave` of frequency f samples its noise for p at p × f turned by a rotation and moved by an offset that
// the seed and octave hash to, with a seed of its own. The turn keeps the octaves' lattices (and those of different
// seeds) out of line: otherwise they would share their zeros, and |noise|, which dips at every lattice point, would
// be correlated across seeds and octaves. The turn, offset and seed depend on the seed and the octave alone.
struct OctaveTurn {
    float turn[3][3];
    Vec3f offset;
    std::uint32_t seed;

    // The domain of the point whose coordinates times the octave's frequency are q.
    OctaveDomain domain(const Vec3f& q) const {
        const Vec3f turned{turn[0][0] * q.x + turn[0][1] * q.y + turn[0][2] * q.z,
                           turn[1][0] * q.x + turn[1][1] * q.y + turn[1][2] * q.z,
                           turn[2][0] * q.x + turn[2][1] * q.y + turn[2][2] * q.z};
        return {turned + offset, seed};
    }
};
OctaveTurn octave_turn(std::uint32_t seed, int octave);

// Fractal settings clamped as documented above, with every octave's turn taken once rather than hashed again at
// every point the sum is evaluated at (heap_bytes for the turns).
class FractalOctaves {
public:
    explicit FractalOctaves(const FractalSettings& settings = {});
    // What the turns of these settings take on the heap, for the memory budget.
    static std::size_t heap_bytes(const FractalSettings& settings);

    const FractalSettings& settings() const { return settings_; }  // as given, unclamped
    int count() const { return count_; }
    float lacunarity() const { return lacunarity_; }
    float gain() const { return gain_; }
    const OctaveTurn& turn(int octave) const { return turns_[std::size_t(octave)]; }

private:
    static int clamped_count(const FractalSettings& settings);

    FractalSettings settings_;
    int count_;
    float lacunarity_, gain_;
    std::vector<OctaveTurn> turns_;  // count_ of them
};

// The footprint is the width of a pixel at p in the units of p (0 = a point sample). An octave of wavelength λ is
// whole while λ ≥ 4 footprints, gone at λ ≤ 2 footprints (where it would alias) and fades smoothly in between:
// a faded octave is replaced by its mean, so the result tends to the pattern's mean, and a gone octave's noise is
// not evaluated. The normalisation counts every octave, faded or not, so the fade never rescales the others.

// The sum of octaves divided by the sum of their amplitudes: within [-1, 1], mean 0.
float fbm(const Vec3f& p, const FractalOctaves& octaves, float footprint);

// The same sum of |noise|: within [0, 1].
float turbulence(const Vec3f& p, const FractalOctaves& octaves, float footprint);

// Musgrave's ridged multifractal with offset 1 and feedback gain 2: each octave is (1 − |noise|)², weighted by
// twice the previous octave's weighted value (clamped to [0, 1]), so ridges carry detail and valleys stay smooth.
// Within [0, 1]. Its fade also fades the weight an octave hands on towards that weight's mean, so that the mean
// over space stays put to first order (within 0.015 at the default settings when every octave has faded).
float ridged(const Vec3f& p, const FractalOctaves& octaves, float footprint);

// The noise that NoiseBasis names.
float basis_noise(NoiseBasis basis, const Vec3f& p, std::uint32_t seed);

// How much of an octave of frequency `frequency` a footprint keeps: 1 while frequency × footprint ≤ 1/4, 0 from
// 1/2, smooth in between.
float octave_fade(float frequency, float footprint);

}  // namespace isotrace
