#pragma once
// The texture system's noises as expression terms: the same functions (so a surface and a texture built from the
// same noise agree exactly), each with the constants that make its interval bounds guaranteed: a Lipschitz
// constant L (|∇n| ≤ L, derived from each noise's construction in docs/decisions.md) and the range of its values.
#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"
#include "renderer/textures/patterns/fractal_noise.h"

namespace isotrace {

enum class NoiseKind { Gradient, Simplex, Fbm, Turbulence, Cellular };

// One gradient-noise octave of a term: it samples gradient_noise(turn × q + offset, seed) (turn is the octave's
// rotation times its frequency, read off the textures' own octave turns) with weight `weight` in the sum.
struct NoiseOctave {
    double turn[3][3] = {};
    Vec3d offset;
    double frequency = 1;
    double weight = 1;
    std::uint32_t seed = 0;
};

struct NoiseTerm {
    NoiseKind kind = NoiseKind::Gradient;
    FractalOctaves fractal;  // Fbm, Turbulence (gradient-noise basis); its seed serves every kind
    float jitter = 0.5f;      // Cellular: at most ½, where the cellular search always finds the nearest point
    double lipschitz = 0;     // |∇n| ≤ lipschitz everywhere
    Interval range;           // every value of n
    double step = 0;          // the central-difference step of the gradient, a small part of the finest detail
    std::vector<NoiseOctave> octaves;  // Gradient, Fbm, Turbulence: bounded cell by cell over small boxes
};

// A term with its bounds; the settings are clamped as the textures clamp them, jitter to [0, ½].
NoiseTerm make_noise_term(NoiseKind kind, const FractalSettings& fractal, float jitter);

// The noise at q, exactly as the textures compute it (in float, footprint 0: a point sample).
double noise_value(const NoiseTerm& term, const Vec3d& q);
// Its gradient: for the gradient-noise kinds the formula's (each octave's, carried through its turn), for simplex
// and cellular noise central differences of the float values.
Vec3d noise_gradient(const NoiseTerm& term, const Vec3d& q);
// What bounds the noise over a box, for its value and its derivative along any motion (computed once when
// several motions are asked, as for the three partial derivatives): the value's interval, and for the
// gradient-noise kinds the octaves' gradient bounds where an octave's box spans few cells.
struct NoiseBoxRanges {
    Interval value;
    std::optional<IntervalBox> gradient;  // ∇n over the box, apart from a part of length at most `reach`
    double reach = 0;
};
// The value's interval is the centre's value ± L × the box's half-diagonal, plus an allowance for the float
// evaluation, within the noise's range; for the gradient-noise kinds intersected with the octaves' formulas
// evaluated in interval arithmetic (gradient_noise_bounds).
NoiseBoxRanges noise_box_ranges(const NoiseTerm& term, const IntervalBox& box);
// noise_box_ranges' value alone.
Interval noise_value_range(const NoiseTerm& term, const IntervalBox& box);
// An interval holding the noise's derivative d/dt n(q(t)) wherever q lies in the box and q′ in `motion`: ±L|q′|,
// intersected with the octaves' gradient bounds where there are some.
Interval noise_slope_range(const NoiseTerm& term, const NoiseBoxRanges& ranges, const IntervalBox& motion);

}  // namespace isotrace
