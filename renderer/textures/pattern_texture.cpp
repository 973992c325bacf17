#include "renderer/textures/pattern_texture.h"

#include <algorithm>

#include "renderer/core/memory_budget.h"
#include "renderer/params/scene_node.h"
#include "renderer/textures/patterns/checker.h"
#include "renderer/textures/patterns/grid.h"

namespace isotrace {

float evaluate_pattern(const PatternSettings& settings, const Vec3f& p, bool planar, float footprint) {
    switch (settings.kind) {
        case PatternKind::Checker:
            return planar ? checker_2d({p.x, p.y}, footprint) : checker(p, footprint);
        case PatternKind::Grid:
            return planar ? grid_2d({p.x, p.y}, settings.line_width, footprint)
                          : grid(p, settings.line_width, footprint);
        case PatternKind::Noise:
            return 0.5f + 0.5f * basis_noise(settings.fractal.settings().basis, p, settings.fractal.settings().seed);
        case PatternKind::Fbm:
            return 0.5f + 0.5f * fbm(p, settings.fractal, footprint);
        case PatternKind::Turbulence:
            return turbulence(p, settings.fractal, footprint);
        case PatternKind::Ridged:
            return ridged(p, settings.fractal, footprint);
        case PatternKind::Cellular:
            return cellular(p, settings.fractal.settings().seed, settings.jitter, settings.cellular_output, footprint);
        case PatternKind::Ramp:
            return ramp(p, settings.ramp_shape);
    }
    return 0;
}

float PatternTexture::evaluate(const TextureContext& context) const {
    const ProjectedLookups lookups = projection_.project(context);
    const float footprint = std::max(lookups.footprint[0], lookups.footprint[1]) * footprint_scale_;
    const bool planar = projection_.is_2d();
    if (lookups.count == 1) return evaluate_pattern(settings_, lookups.points[0].point * scale_, planar, footprint);
    float sum = 0;
    for (int i = 0; i < lookups.count; ++i) {
        const ProjectedPoint& lookup = lookups.points[std::size_t(i)];
        sum += evaluate_pattern(settings_, lookup.point * scale_, planar, footprint) * lookup.weight;
    }
    return sum;
}

const std::vector<std::string>& pattern_types() {
    static const std::vector<std::string> names{"checker",    "grid",   "noise",    "fbm",
                                                "turbulence", "ridged", "cellular", "ramp"};
    return names;
}

namespace {

template <class Enum>
Enum choice(const SceneNode& node, const std::string& key, const std::vector<std::string>& names, int fallback) {
    const std::string value = node.choice_or(key, names[std::size_t(fallback)], names);
    return Enum(std::find(names.begin(), names.end(), value) - names.begin());
}

}  // namespace

ScalarTexturePtr parse_pattern(const SceneNode& node, const std::string& type) {
    PatternSettings settings;
    settings.kind = PatternKind(std::find(pattern_types().begin(), pattern_types().end(), type) - pattern_types().begin());
    const PatternKind kind = settings.kind;
    const bool fractal = kind == PatternKind::Fbm || kind == PatternKind::Turbulence || kind == PatternKind::Ridged;
    FractalSettings noise;
    if (fractal || kind == PatternKind::Noise) {
        noise.basis = choice<NoiseBasis>(node, "basis", {"gradient", "simplex"}, 0);
        noise.seed = std::uint32_t(node.integer_or("seed", 0, NumberRange::between(0, 2147483647)));
    }
    noise.octaves = 0;  // the other patterns sum no octaves
    if (fractal) {
        noise.octaves = node.integer_or("octaves", 5, NumberRange::between(0, kMaxFractalOctaves));
        noise.lacunarity = float(node.number_or("lacunarity", 2, NumberRange::between(1, 16)));
        noise.gain = float(node.number_or("gain", 0.5, NumberRange::between(0, 4)));
    }
    if (kind == PatternKind::Cellular) {
        noise.seed = std::uint32_t(node.integer_or("seed", 0, NumberRange::between(0, 2147483647)));
        settings.jitter = float(node.number_or("jitter", 1, NumberRange::unit_interval()));
        settings.cellular_output = choice<CellularOutput>(node, "output", {"f1", "f2", "f2_minus_f1", "cell_value"}, 0);
    }
    if (const std::size_t bytes = FractalOctaves::heap_bytes(noise); bytes > 0 && node.context().memory)
        node.context().memory->charge(bytes, "a fractal pattern's octaves", node.location());
    settings.fractal = FractalOctaves(noise);
    if (kind == PatternKind::Grid)
        settings.line_width = float(node.number_or("line_width", 0.1, NumberRange::unit_interval()));
    if (kind == PatternKind::Ramp)
        settings.ramp_shape = choice<RampShape>(node, "shape", {"linear", "smooth", "spherical", "radial"}, 0);
    Vec3f scale{1, 1, 1};
    if (const auto value = node.optional_value("scale")) {
        const NumberRange frequency{0, 1e6, true, false};
        if (value->json().is_number()) {
            scale = Vec3f(1, 1, 1) * float(value->as_number(frequency));
        } else {
            const std::vector<double> factors = node.numbers("scale", 3, frequency);
            scale = {float(factors[0]), float(factors[1]), float(factors[2])};
        }
    }
    const Projection projection = parse_projection(node, "projection", ProjectionKind::Solid);
    return std::make_shared<PatternTexture>(settings, projection, scale);
}

}  // namespace isotrace
