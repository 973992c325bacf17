#pragma once
// A procedural pattern (renderer/textures/patterns) as a scalar texture: the pattern at the projected point times
// `scale` (a frequency), band-limited by the footprint. Noise and fBm, in [-1, 1], are mapped to [0, 1]; the
// other patterns give their own values (docs/textures.md, "Patterns").
#include <string>
#include <vector>

#include "renderer/textures/patterns/cellular_noise.h"
#include "renderer/textures/patterns/fractal_noise.h"
#include "renderer/textures/patterns/ramp.h"
#include "renderer/textures/projection.h"

namespace isotrace {

class SceneNode;

enum class PatternKind { Checker, Grid, Noise, Fbm, Turbulence, Ridged, Cellular, Ramp };

struct PatternSettings {
    PatternKind kind = PatternKind::Checker;
    FractalOctaves fractal;  // noise and cellular read its seed, noise its basis
    float jitter = 1;
    CellularOutput cellular_output = CellularOutput::F1;
    float line_width = 0.1f;
    RampShape ramp_shape = RampShape::Linear;
};

// The pattern at p; `planar`: p is a 2-D lookup (z = 0), for which the checker and grid have 2-D forms.
float evaluate_pattern(const PatternSettings& settings, const Vec3f& p, bool planar, float footprint);

class PatternTexture final : public ScalarTexture {
public:
    PatternTexture(const PatternSettings& settings, const Projection& projection, const Vec3f& scale)
        : settings_(settings), projection_(projection), scale_(scale), footprint_scale_(max_component(scale)) {}

    float evaluate(const TextureContext& context) const override;
    TextureNeeds needs() const override { return projection_.needs(); }

private:
    PatternSettings settings_;
    Projection projection_;
    Vec3f scale_;
    float footprint_scale_;  // the footprint in pattern units per unit of the projection's
};

// The names of the pattern "type"s.
const std::vector<std::string>& pattern_types();

// A node whose "type" is one of pattern_types(): its settings, "scale" and "projection" (the node's other keys, such
// as "a" and "b", are the caller's).
ScalarTexturePtr parse_pattern(const SceneNode& node, const std::string& type);

}  // namespace isotrace
