#pragma once
// Ramps: a value in [0, 1] that varies along one direction or around one point or axis.
#include "renderer/math/vec3.h"

namespace isotrace {

enum class RampShape {
    Linear,     // x clamped to [0, 1]
    Smooth,     // the same through smoothstep 3t² − 2t³: flat at both ends
    Spherical,  // 1 − |p| clamped to [0, 1]: 1 at the origin, 0 from the unit sphere out
    Radial,     // the angle around the z axis from +x, counter-clockwise, over 2π: in [0, 1), the seam on +x
};

// In [0, 1]; not filtered (a ramp is smooth except for the radial seam and the clamps' corners). A NaN coordinate
// gives 0.
float ramp(const Vec3f& p, RampShape shape);

}  // namespace isotrace
