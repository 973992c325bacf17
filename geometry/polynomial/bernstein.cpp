#include "geometry/polynomial/bernstein.h"

namespace isotrace {

BernsteinCoefficients to_bernstein(const Polynomial& on_unit_interval) {
    using namespace bernstein_detail;
    const int n = on_unit_interval.degree();
    Double4 value[kCoefficientQuads], magnitude[kCoefficientQuads];
    bernstein_values(on_unit_interval, n, value, magnitude);
    const double relative_error = relative_conversion_error(n);
    BernsteinCoefficients result;
    result.degree = n;
    for (int k = 0; k <= n; ++k) {
        result.values[std::size_t(k)] = value[k / 4][k % 4];
        result.error_bounds[std::size_t(k)] = relative_error * magnitude[k / 4][k % 4];
    }
    return result;
}

}  // namespace isotrace
