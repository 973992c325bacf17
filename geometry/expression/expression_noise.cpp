#include "geometry/expression/expression_noise.h"

#include <algorithm>
#include <cmath>

#include "geometry/expression/gradient_noise_bounds.h"
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

FractalScale fractal_scale(const FractalOctaves& fractal) {
    FractalScale scale;
    double frequency = 1, amplitude = 1, weighted = 0, total = 0;
    for (int octave = 0; octave < fractal.count(); ++octave) {
        weighted += amplitude * frequency;
        total += amplitude;
        scale.finest_frequency = frequency;
        frequency *= fractal.lacunarity();
        amplitude *= fractal.gain();
    }
    scale.lipschitz_factor = total > 0 ? weighted / total : 0;
    return scale;
}

// The octaves of fractal_sum (its float frequencies and amplitudes), each octave's affine map read off its turn's
// domain at the octave's frequency: the offset is the image of 0 (exact), a column of the turn the image of a large
// multiple of an axis less the offset (so that the float rounding of the image is a small part of it).
std::vector<NoiseOctave> fractal_octaves(const FractalOctaves& fractal) {
    constexpr float kProbe = 4096;
    std::vector<NoiseOctave> octaves;
    float frequency = 1, amplitude = 1, total = 0;
    for (int index = 0; index < fractal.count(); ++index) {
        NoiseOctave octave;
        const OctaveTurn& turn = fractal.turn(index);
        const OctaveDomain origin = turn.domain(Vec3f{0, 0, 0});
        octave.offset = Vec3d(origin.point);
        for (int k = 0; k < 3; ++k) {
            Vec3f axis{0, 0, 0};
            axis[k] = kProbe;
            const Vec3d image(turn.domain(axis * frequency).point);
            for (int j = 0; j < 3; ++j) octave.turn[j][k] = (image[j] - octave.offset[j]) / kProbe;
        }
        octave.frequency = frequency;
        octave.weight = amplitude;
        octave.seed = origin.seed;
        octaves.push_back(octave);
        total += amplitude;
        frequency *= fractal.lacunarity();
        amplitude *= fractal.gain();
    }
    for (NoiseOctave& octave : octaves) octave.weight = total > 0 ? octave.weight / total : 0;
    return octaves;
}

Interval intersect(Interval a, Interval b) { return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)}; }

// The noise's values and gradient over a box by its octaves: `gradient` bounds the gradient in q, apart from a
// part of length at most `reach` (from the octaves too fine to bound cell by cell).
struct OctaveSumBounds {
    Interval value;
    IntervalBox gradient;
    double reach = 0;
};

OctaveSumBounds octave_sum_bounds(const NoiseTerm& term, const IntervalBox& box) {
    Vec3d centre, half;
    double size = 0;
    for (int k = 0; k < 3; ++k) {
        centre[k] = 0.5 * (box[k].lo + box[k].hi);
        half[k] = 0.5 * box[k].width();
        size = std::max({size, std::abs(box[k].lo), std::abs(box[k].hi)});
    }
    OctaveSumBounds sum;
    sum.value = Interval::point(0);
    for (const NoiseOctave& octave : term.octaves) {
        // The octave's box: the image of the box, widened for the float rounding of the textures' map.
        const double margin = 0x1p-20 * (octave.frequency * size + 2);
        IntervalBox turned;
        Vec3d turned_centre;
        double half_diagonal_squared = 0;
        for (int j = 0; j < 3; ++j) {
            double radius = margin;
            turned_centre[j] = octave.offset[j];
            for (int k = 0; k < 3; ++k) {
                turned_centre[j] += octave.turn[j][k] * centre[k];
                radius += std::abs(octave.turn[j][k]) * half[k];
            }
            turned[j] = {turned_centre[j] - radius, turned_centre[j] + radius};
            half_diagonal_squared += radius * radius;
        }
        Interval value{-1, 1};
        IntervalBox gradient;
        if (const std::optional<NoiseBoxBounds> bounds = gradient_noise_bounds(turned, octave.seed)) {
            value = intersect(bounds->value, value);
            gradient = bounds->gradient;
        } else {
            // Too many cells: the centre's value ± L × the half-diagonal.
            if (const auto at_centre = gradient_noise_value_at(turned_centre, octave.seed)) {
                const double reach = kGradientNoiseLipschitz * std::sqrt(half_diagonal_squared);
                value = intersect({at_centre->lo - reach, at_centre->hi + reach}, value);
            }
            sum.reach += octave.weight * kGradientNoiseLipschitz * octave.frequency;
        }
        if (term.kind == NoiseKind::Turbulence) {
            // |n|′ = ±n′: the sign is known where n's is.
            if (value.hi < 0)
                for (int j = 0; j < 3; ++j) gradient[j] = -gradient[j];
            else if (!(value.lo > 0))
                for (int j = 0; j < 3; ++j) gradient[j] = hull(gradient[j], -gradient[j]);
            value = value.magnitude();
        }
        sum.value = sum.value + value * octave.weight;
        // ∇_q = weight × turnᵀ ∇.
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) sum.gradient[k] = sum.gradient[k] + gradient[j] * (octave.weight * octave.turn[j][k]);
    }
    return sum;
}

}  // namespace

NoiseTerm make_noise_term(NoiseKind kind, const FractalSettings& fractal, float jitter) {
    NoiseTerm term;
    term.kind = kind;
    FractalSettings settings = fractal;  // FractalOctaves clamps the octaves, lacunarity and gain
    settings.basis = NoiseBasis::Gradient;
    const bool fractal_sum = kind == NoiseKind::Fbm || kind == NoiseKind::Turbulence;
    if (!fractal_sum) settings.octaves = 0;  // the other kinds sum no octaves
    term.fractal = FractalOctaves(settings);
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
    if (kind == NoiseKind::Gradient) {
        term.octaves.resize(1);
        for (int k = 0; k < 3; ++k) term.octaves[0].turn[k][k] = 1;
        term.octaves[0].seed = settings.seed;
    } else if (kind == NoiseKind::Fbm || kind == NoiseKind::Turbulence) {
        term.octaves = fractal_octaves(term.fractal);
    }
    return term;
}

double noise_value(const NoiseTerm& term, const Vec3d& q) {
    const Vec3f point = to_float(q);
    switch (term.kind) {
        case NoiseKind::Gradient: return gradient_noise(point, term.fractal.settings().seed);
        case NoiseKind::Simplex: return simplex_noise(point, term.fractal.settings().seed);
        case NoiseKind::Fbm: return fbm(point, term.fractal, 0);
        case NoiseKind::Turbulence: return turbulence(point, term.fractal, 0);
        case NoiseKind::Cellular:
            return cellular(point, term.fractal.settings().seed, term.jitter, CellularOutput::F1, 0);
    }
    return 0;
}

namespace {

// The gradient of a sum of gradient-noise octaves: each octave's formula gradient carried back through its turn
// (∇_q = weight × turnᵀ ∇), with the sign of the octave's value for turbulence's |n|.
Vec3d octave_sum_gradient(const NoiseTerm& term, const Vec3d& q) {
    const Vec3f point = to_float(q);
    Vec3d sum{0, 0, 0};
    for (std::size_t index = 0; index < term.octaves.size(); ++index) {
        const NoiseOctave& octave = term.octaves[index];
        const OctaveDomain domain =
            term.fractal.turn(static_cast<int>(index)).domain(point * static_cast<float>(octave.frequency));
        Vec3d g(gradient_noise_gradient(domain.point, domain.seed));
        if (term.kind == NoiseKind::Turbulence && gradient_noise(domain.point, domain.seed) < 0) g = -g;
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) sum[k] += octave.weight * octave.turn[j][k] * g[j];
    }
    return sum;
}

}  // namespace

Vec3d noise_gradient(const NoiseTerm& term, const Vec3d& q) {
    switch (term.kind) {
        case NoiseKind::Gradient: return Vec3d(gradient_noise_gradient(to_float(q), term.fractal.settings().seed));
        case NoiseKind::Fbm:
        case NoiseKind::Turbulence: return octave_sum_gradient(term, q);
        case NoiseKind::Simplex:
        case NoiseKind::Cellular: break;
    }
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

namespace {

// The value range by the Lipschitz bound alone; `size` is set to the box's largest coordinate.
Interval lipschitz_value_range(const NoiseTerm& term, const IntervalBox& box, double& size) {
    double half_diagonal_squared = 0;
    Vec3d centre;
    size = 0;
    for (int k = 0; k < 3; ++k) {
        centre[k] = 0.5 * (box[k].lo + box[k].hi);
        half_diagonal_squared += 0.25 * box[k].width() * box[k].width();
        size = std::max({size, std::abs(box[k].lo), std::abs(box[k].hi)});
    }
    if (!std::isfinite(half_diagonal_squared) || !std::isfinite(centre.x + centre.y + centre.z)) return term.range;
    const double reach = term.lipschitz * std::sqrt(half_diagonal_squared) + rounding_allowance(term, size);
    const double at_centre = noise_value(term, centre);
    return intersect({at_centre - reach, at_centre + reach}, term.range);
}

// The octaves' value range with the float allowance, within the Lipschitz one.
Interval value_within(const NoiseTerm& term, const OctaveSumBounds& bounds, double size, Interval lipschitz_range) {
    const Interval allowance{-rounding_allowance(term, size), rounding_allowance(term, size)};
    return intersect(bounds.value + allowance, lipschitz_range);
}

}  // namespace

NoiseBoxRanges noise_box_ranges(const NoiseTerm& term, const IntervalBox& box) {
    double size = 0;
    const Interval lipschitz_range = lipschitz_value_range(term, box, size);
    if (term.octaves.empty() || !box.is_finite()) return {lipschitz_range, std::nullopt};
    const OctaveSumBounds bounds = octave_sum_bounds(term, box);
    return {value_within(term, bounds, size, lipschitz_range), bounds.gradient, bounds.reach};
}

Interval noise_value_range(const NoiseTerm& term, const IntervalBox& box) { return noise_box_ranges(term, box).value; }

Interval noise_slope_range(const NoiseTerm& term, const NoiseBoxRanges& ranges, const IntervalBox& motion) {
    double speed_squared = 0;
    for (int k = 0; k < 3; ++k) speed_squared += motion[k].magnitude().hi * motion[k].magnitude().hi;
    const double speed = std::sqrt(speed_squared);
    const Interval lipschitz_slope{-term.lipschitz * speed, term.lipschitz * speed};
    if (!ranges.gradient || !std::isfinite(speed)) return lipschitz_slope;
    Interval slope{-ranges.reach * speed, ranges.reach * speed};
    for (int k = 0; k < 3; ++k) slope = slope + (*ranges.gradient)[k] * motion[k];
    return intersect(slope, lipschitz_slope);
}

}  // namespace isotrace
