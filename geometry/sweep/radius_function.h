#pragma once
// r(θ, t) of a sweep: at each key section a closed C² cubic spline in θ through the sampled radii (eq. 2: equal
// values and derivatives at 0 and 2π), and between key sections a cubic interpolating B-spline in t on the same
// knots as the centre curve (or, `shape_preserving`, the centre curve's shape-preserving piecewise cubic on each
// θ control column). Both interpolations are linear, so r is one tensor-product B-spline.
#include <vector>

#include "geometry/curves/knot_vector.h"

namespace isotrace {

class RadiusFunction {
public:
    // radii[k] are the m samples of key k (all of the same length m ≥ 3), parameters[k] its t.
    RadiusFunction(const std::vector<std::vector<double>>& radii, const std::vector<double>& parameters,
                   bool shape_preserving = false);

    double operator()(double theta, double t) const;
    int samples() const { return samples_; }

private:
    int samples_;
    KnotVector t_knots_;
    KnotVector theta_knots_;        // uniform cubic: one period spans m knot intervals
    std::vector<double> control_;   // [t control i][θ control j], row-major, m columns
};

}  // namespace isotrace
