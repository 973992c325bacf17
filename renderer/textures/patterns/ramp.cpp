#include "renderer/textures/patterns/ramp.h"

#include <cmath>
#include <numbers>

#include "renderer/textures/patterns/pattern_math.h"

namespace isotrace {

float ramp(const Vec3f& p, RampShape shape) {
    switch (shape) {
        case RampShape::Linear: return unit_clamp(p.x);
        case RampShape::Smooth: return smoothstep(0, 1, p.x);
        case RampShape::Spherical: return unit_clamp(1 - length(p));
        case RampShape::Radial: {
            const float turns = std::atan2(p.y, p.x) / (2 * std::numbers::pi_v<float>);
            const float wrapped = turns < 0 ? turns + 1 : turns;
            return wrapped < 1 ? unit_clamp(wrapped) : 0.0f;  // just below the seam, turns + 1 may round to 1
        }
    }
    return 0;
}

}  // namespace isotrace
