#include "geometry/expression/expression_noise.h"

#include <algorithm>
#include <cmath>

#include "renderer/textures/patterns/cellular_noise.h"
#include "renderer/textures/patterns/gradient_noise.h"
#include "renderer/textures/patterns/simplex_noise.h"

namespace isotrace {
namespace {

// Bounds of |∇n| for one octave of each basis, derived in docs/decisions.md ("Expression noises: Lipschitz
// bounds") and checked against dense sampling by expression_noise_test.
constexpr double kGradientNoiseLipschitz = 10.8;
constexpr double kSimplexNoiseLipschitz = 34.3;
// F1 is the distance to the nearest of a set of points: a minimum of 1-Lipschitz functions.
constexpr double kCellularLipschitz = 1;

// The gradient's step in units of the finest lattice cell: small against the detail, large against float
// rounding of the noise's coordinates.
constexpr double kRelativeStep = 1e-3;

// The noise and its sampled point are floats: the allowance for their rounding (an absolute part for the noise's
// arithmetic, a part relative to the coordinates' size scaled by L for the rounded point).
double rounding_allowance(const NoiseTerm& term, double coordinate_size) {
    return 1e-5 + term.lipschitz * (coordinate_size + 1) * 0x1p-19;
}

Vec3f to_float(const Vec3d& q) {
    return {static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z)};
}

// Σ amplitude × frequency over the octaves, divided by Σ amplitude (the normalisation of fractal_sum), and the
// highest frequency.
struct FractalScale {
    double lipschitz_factor = 0, finest_frequency = 1;
};

FractalScale fractal_scale(const FractalSettings& settings) {
    FractalScale scale;
    double frequency = 1, amplitude = 1, weighted = 0, total = 0;
    for (int octave = 0; octave < settings.octaves; ++octave) {
        weighted += amplitude * frequency;
        total += amplitude;
        scale.finest_frequency = frequency;
        frequency *= settings.lacunarity;
        amplitude *= settings.gain;
    }
    scale.lipschitz_factor = total > 0 ? weighted / total : 0;
    return scale;
}

}  // namespace

NoiseTerm make_noise_term(NoiseKind kind, const FractalSettings& fractal, float jitter) {
    NoiseTerm term;
    term.kind = kind;
    term.fractal = fractal;
    term.fractal.basis = NoiseBasis::Gradient;
    term.fractal.octaves = std::clamp(fractal.octaves, 0, kMaxFractalOctaves);
    term.fractal.lacunarity = std::clamp(fractal.lacunarity, 1.0f, 16.0f);
    term.fractal.gain = std::clamp(fractal.gain, 0.0f, 4.0f);
    term.jitter = std::clamp(jitter, 0.0f, 0.5f);
    double finest_frequency = 1;
    switch (kind) {
        case NoiseKind::Gradient:
            term.lipschitz = kGradientNoiseLipschitz;
            term.range = {-1, 1};
            break;
        case NoiseKind::Simplex:
            term.lipschitz = kSimplexNoiseLipschitz;
            term.range = {-1, 1};
            break;
        case NoiseKind::Fbm:
        case NoiseKind::Turbulence: {
            const FractalScale scale = fractal_scale(term.fractal);
            term.lipschitz = kGradientNoiseLipschitz * scale.lipschitz_factor;
            finest_frequency = scale.finest_frequency;
            term.range = kind == NoiseKind::Fbm ? Interval{-1, 1} : Interval{0, 1};
            break;
        }
        case NoiseKind::Cellular:
            term.lipschitz = kCellularLipschitz;
            term.range = {0, std::sqrt(3.0)};
            break;
    }
    term.step = kRelativeStep / finest_frequency;
    return term;
}

double noise_value(const NoiseTerm& term, const Vec3d& q) {
    const Vec3f point = to_float(q);
    switch (term.kind) {
        case NoiseKind::Gradient: return gradient_noise(point, term.fractal.seed);
        case NoiseKind::Simplex: return simplex_noise(point, term.fractal.seed);
        case NoiseKind::Fbm: return fbm(point, term.fractal, 0);
        case NoiseKind::Turbulence: return turbulence(point, term.fractal, 0);
        case NoiseKind::Cellular: return cellular(point, term.fractal.seed, term.jitter, CellularOutput::F1, 0);
    }
    return 0;
}

Vec3d noise_gradient(const NoiseTerm& term, const Vec3d& q) {
    const double size = std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    const double h = std::max(term.step, size * 0x1p-17);  // dozens of float ulps of q at least
    Vec3d gradient;
    for (int k = 0; k < 3; ++k) {
        Vec3d ahead = q, behind = q;
        ahead[k] += h;
        behind[k] -= h;
        gradient[k] = (noise_value(term, ahead) - noise_value(term, behind)) / (2 * h);
    }
    return gradient;
}

Interval noise_value_range(const NoiseTerm& term, const IntervalBox& box) {
    double half_diagonal_squared = 0, size = 0;
    Vec3d centre;
    for (int k = 0; k < 3; ++k) {
        centre[k] = 0.5 * (box[k].lo + box[k].hi);
        half_diagonal_squared += 0.25 * box[k].width() * box[k].width();
        size = std::max({size, std::abs(box[k].lo), std::abs(box[k].hi)});
    }
    if (!std::isfinite(half_diagonal_squared) || !std::isfinite(centre.x + centre.y + centre.z)) return term.range;
    const double reach = term.lipschitz * std::sqrt(half_diagonal_squared) + rounding_allowance(term, size);
    const double at_centre = noise_value(term, centre);
    return {std::max(at_centre - reach, term.range.lo), std::min(at_centre + reach, term.range.hi)};
}

}  // namespace isotrace
