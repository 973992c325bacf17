#include "renderer/textures/patterns/fractal_noise.h"

#include <algorithm>
#include <cmath>

#include "renderer/textures/patterns/gradient_noise.h"
#include "renderer/textures/patterns/lattice.h"
#include "renderer/textures/patterns/pattern_math.h"
#include "renderer/textures/patterns/simplex_noise.h"

namespace isotrace {
namespace {

// Measured statistics of each basis's noise n over space (fractal_noise_test checks them through the means of
// faded patterns).
struct BasisStatistics {
    float absolute_mean;  // E|n|
    float ridge_mean;     // E(1 − |n|)²
    // E min(1, 2w(1 − |n|)²), the mean feedback weight after a ridged octave entered with weight w, at
    // w = 1/2, 9/16, …, 1; below 1/2 it is 2w × ridge_mean (the clamp is never reached).
    float feedback[9];
};

constexpr BasisStatistics kGradientStatistics{
    0.2124f, 0.6430f, {0.6429f, 0.7128f, 0.7664f, 0.8081f, 0.8411f, 0.8673f, 0.8883f, 0.9053f, 0.9190f}};
constexpr BasisStatistics kSimplexStatistics{
    0.3138f, 0.5262f, {0.5259f, 0.5841f, 0.6301f, 0.6670f, 0.6972f, 0.7222f, 0.7433f, 0.7612f, 0.7767f}};

const BasisStatistics& basis_statistics(NoiseBasis basis) {
    return basis == NoiseBasis::Simplex ? kSimplexStatistics : kGradientStatistics;
}

// The mean over space of the next octave's ridged weight, given this octave's weight.
float mean_feedback(const BasisStatistics& statistics, float weight) {
    if (weight <= 0.5f) return 2 * weight * statistics.ridge_mean;
    const float position = std::min((weight - 0.5f) * 16, 7.999f);
    const int node = static_cast<int>(position);
    const float t = position - static_cast<float>(node);
    return statistics.feedback[node] + t * (statistics.feedback[node + 1] - statistics.feedback[node]);
}

// Clamps as FractalSettings documents; NaN goes to the lower bound.
float clamp_or_low(float value, float low, float high) {
    return value > low ? std::min(value, high) : low;
}

// An octave's shaped noise faded towards its mean.
float faded(float shaped, float fade, float mean) {
    return mean + fade * (shaped - mean);
}

// The fractal sum shared by fbm, turbulence and ridged: octave i's noise goes through `shape`, and `term` turns it
// and the octave's fade (0 = gone: the noise was not evaluated, and `shaped_mean` stands in for it) into the
// octave's term; the terms are weighted by the amplitudes and divided by their sum.
template <class Shape, class Term>
float fractal_sum(const Vec3f& p, const FractalOctaves& octaves, float footprint, float shaped_mean, Shape shape,
                  Term term) {
    const NoiseBasis basis = octaves.settings().basis;
    float frequency = 1, amplitude = 1, sum = 0, total = 0;
    for (int octave = 0; octave < octaves.count(); ++octave) {
        const float fade = octave_fade(frequency, footprint);
        float shaped = shaped_mean;
        if (fade > 0) {
            const OctaveDomain domain = octaves.turn(octave).domain(p * frequency);
            shaped = shape(basis_noise(basis, domain.point, domain.seed));
        }
        sum += amplitude * term(shaped, fade);
        total += amplitude;
        frequency *= octaves.lacunarity();
        amplitude *= octaves.gain();
    }
    return total > 0 ? sum / total : shaped_mean;
}

float ridge(float noise) {
    const float signal = 1 - std::abs(noise);
    return signal * signal;
}

}  // namespace

float basis_noise(NoiseBasis basis, const Vec3f& p, std::uint32_t seed) {
    return basis == NoiseBasis::Simplex ? simplex_noise(p, seed) : gradient_noise(p, seed);
}

OctaveTurn octave_turn(std::uint32_t seed, int octave) {
    // Eight independent 32-bit random numbers from one hash of (seed, octave).
    const std::uint32_t hash = lattice_hash(lattice_seed(seed), octave);
    std::uint32_t bits[8];
    for (std::uint32_t i = 0; i < 8; ++i) bits[i] = hash_stream(hash, i + 1);
    const auto random = [&bits](int i) { return 2 * uint_to_unit_float(bits[i]) - 1; };  // in [-1, 1)
    // The rotation of the quaternion (w, x, y, z), scaled by s = 2 / |q|² instead of normalising q.
    const float w = random(0), x = random(1), y = random(2), z = random(3);
    const float norm_squared = w * w + x * x + y * y + z * z;
    const float s = norm_squared > 1e-6f ? 2 / norm_squared : 0;
    return {{{1 - s * (y * y + z * z), s * (x * y - w * z), s * (x * z + w * y)},
             {s * (x * y + w * z), 1 - s * (x * x + z * z), s * (y * z - w * x)},
             {s * (x * z - w * y), s * (y * z + w * x), 1 - s * (x * x + y * y)}},
            Vec3f(random(4), random(5), random(6)),
            bits[7]};
}

FractalOctaves::FractalOctaves(const FractalSettings& settings)
    : settings_(settings),
      count_(clamped_count(settings)),
      lacunarity_(clamp_or_low(settings.lacunarity, 1, 16)),
      gain_(clamp_or_low(settings.gain, 0, 4)) {
    turns_.reserve(std::size_t(count_));
    for (int octave = 0; octave < count_; ++octave) turns_.push_back(octave_turn(settings.seed, octave));
}

std::size_t FractalOctaves::heap_bytes(const FractalSettings& settings) {
    return std::size_t(clamped_count(settings)) * sizeof(OctaveTurn);
}

int FractalOctaves::clamped_count(const FractalSettings& settings) {
    return std::clamp(settings.octaves, 0, kMaxFractalOctaves);
}

float octave_fade(float frequency, float footprint) {
    return 1 - smoothstep(0.25f, 0.5f, frequency * footprint_or_zero(footprint));
}

float fbm(const Vec3f& p, const FractalOctaves& octaves, float footprint) {
    return fractal_sum(p, octaves, footprint, 0.0f, [](float noise) { return noise; },
                       [](float shaped, float fade) { return faded(shaped, fade, 0); });
}

float turbulence(const Vec3f& p, const FractalOctaves& octaves, float footprint) {
    const float mean = basis_statistics(octaves.settings().basis).absolute_mean;
    return fractal_sum(p, octaves, footprint, mean, [](float noise) { return std::abs(noise); },
                       [mean](float shaped, float fade) { return faded(shaped, fade, mean); });
}

// The fade keeps the mean over space to first order: an octave's term is its weight times its faded signal, whose
// mean is the weight times the signal's mean, and the weight handed on is faded towards its mean given the weight
// received (mean_feedback), so a faded octave passes on what the whole one would on average. (Only to first order:
// the mean of the next weight is propagated, not its distribution.)
float ridged(const Vec3f& p, const FractalOctaves& octaves, float footprint) {
    const BasisStatistics& statistics = basis_statistics(octaves.settings().basis);
    float weight = 1;  // the first octave is whole; each later one is weighted by its predecessor
    return fractal_sum(p, octaves, footprint, statistics.ridge_mean, ridge, [&](float shaped, float fade) {
        const float term = weight * faded(shaped, fade, statistics.ridge_mean);
        weight = faded(std::min(2 * weight * shaped, 1.0f), fade, mean_feedback(statistics, weight));
        return term;
    });
}

}  // namespace isotrace
