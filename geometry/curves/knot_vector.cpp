#include "geometry/curves/knot_vector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace isotrace {

KnotVector::KnotVector(int degree, std::vector<double> knots) : degree_(degree), knots_(std::move(knots)) {
    if (degree_ < 0 || degree_ > kMaxDegree)
        throw std::invalid_argument("degree: must be in [0, " + std::to_string(kMaxDegree) + "], got " +
                                    std::to_string(degree_));
    if (control_count() < degree_ + 1)
        throw std::invalid_argument("knots: a degree-" + std::to_string(degree_) + " B-spline needs at least " +
                                    std::to_string(2 * degree_ + 2) + " knots, got " + std::to_string(knots_.size()));
    for (std::size_t i = 0; i < knots_.size(); ++i) {
        if (!std::isfinite(knots_[i])) throw std::invalid_argument("knots: knot " + std::to_string(i) + " is not finite");
        if (i > 0 && knots_[i] < knots_[i - 1])
            throw std::invalid_argument("knots: knot " + std::to_string(i) + " is smaller than the one before it");
    }
    if (!(domain_end() > domain_start())) throw std::invalid_argument("knots: the curve's domain has zero length");
}

KnotVector KnotVector::clamped_uniform(int degree, int control_count) {
    const int segments = control_count - degree;
    std::vector<double> knots;
    for (int i = 0; i < degree; ++i) knots.push_back(0);
    for (int i = 0; i <= std::max(segments, 0); ++i) knots.push_back(double(i) / std::max(segments, 1));
    for (int i = 0; i < degree; ++i) knots.push_back(1);
    return {degree, std::move(knots)};
}

KnotVector KnotVector::uniform(int degree, int control_count) {
    std::vector<double> knots;
    for (int i = 0; i < control_count + degree + 1; ++i) knots.push_back(i);
    return {degree, std::move(knots)};
}

KnotVector KnotVector::averaged(int degree, const std::vector<double>& parameters) {
    const int n = int(parameters.size()) - 1;
    std::vector<double> knots(std::size_t(n + degree + 2));
    for (int i = 0; i <= degree; ++i) {
        knots[std::size_t(i)] = 0;
        knots[std::size_t(n + 1 + i)] = 1;
    }
    for (int j = 1; j <= n - degree; ++j) {
        double sum = 0;
        for (int i = j; i < j + degree; ++i) sum += parameters[std::size_t(i)];
        knots[std::size_t(j + degree)] = sum / degree;
    }
    return {degree, std::move(knots)};
}

double KnotVector::to_knot(double t) const {
    t = std::clamp(t, 0.0, 1.0);
    return domain_start() + t * (domain_end() - domain_start());
}

int KnotVector::span(double u) const {
    const int last = control_count() - 1;
    if (u >= knots_[std::size_t(last + 1)]) {
        // The domain end belongs to the last span of non-zero length.
        int i = last;
        while (i > degree_ && knots_[std::size_t(i)] == knots_[std::size_t(i + 1)]) --i;
        return i;
    }
    if (u <= knots_[std::size_t(degree_)]) {
        int i = degree_;
        while (i < last && knots_[std::size_t(i)] == knots_[std::size_t(i + 1)]) ++i;
        return i;
    }
    // The last knot u_i ≤ u among u_p … u_{last}.
    const auto begin = knots_.begin() + degree_, end = knots_.begin() + last + 1;
    return int(std::upper_bound(begin, end, u) - knots_.begin()) - 1;
}

void KnotVector::basis(int span, double u, double* values) const {
    // Triangular scheme: left[j] = u − u_{span+1−j}, right[j] = u_{span+j} − u.
    double left[kMaxDegree + 1], right[kMaxDegree + 1];
    values[0] = 1;
    for (int j = 1; j <= degree_; ++j) {
        left[j] = u - knots_[std::size_t(span + 1 - j)];
        right[j] = knots_[std::size_t(span + j)] - u;
        double saved = 0;
        for (int r = 0; r < j; ++r) {
            const double denominator = right[r + 1] + left[j - r];
            const double temp = denominator == 0 ? 0 : values[r] / denominator;
            values[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        values[j] = saved;
    }
}

}  // namespace isotrace
