#pragma once
// The analytic box filter of the periodic patterns (checker, grid): the mean of a function over a footprint, from
// its antiderivative, one axis at a time (a box is separable).
#include <algorithm>
#include <cmath>

namespace isotrace {

// Beyond this footprint a pattern of unit period differs from its mean by less than 2^-20: the mean is returned
// (and an infinite footprint never reaches the antiderivative).
constexpr double kWideFootprint = 0x1p20;

// The mean of f over [x − width/2, x + width/2]: (F(x + width/2) − F(x − width/2)) / width with F an
// antiderivative of f. A width below the float spacing at x cannot move a float sample and would leave only the
// rounding of that difference: f(x) is returned. `mean` is f's mean over a period.
template <class Function, class Antiderivative>
double box_filtered(Function f, Antiderivative antiderivative, double mean, double x, double width) {
    if (width <= 0x1p-23 * std::max(1.0, std::abs(x))) return f(x);
    if (width >= kWideFootprint) return mean;
    return (antiderivative(x + width / 2) - antiderivative(x - width / 2)) / width;
}

}  // namespace isotrace
