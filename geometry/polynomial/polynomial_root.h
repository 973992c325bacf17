#pragma once
// The vocabulary shared by the root finders: how precisely to locate a root, and what is reported.
#include <array>
#include <cmath>
#include <cstdint>

#include "geometry/polynomial/polynomial.h"

namespace isotrace {

// A root is located to within absolute + relative·|t|. Newton converges quadratically, so tight defaults cost
// about one extra iteration.
struct RootTolerance {
    double absolute = 1e-13;
    double relative = 1e-13;
    double width_at(double t) const { return absolute + relative * std::abs(t); }
};

// Work done by a root finder, for statistics: its refinement steps (Newton or bisection), summed over calls.
struct RootFinderWork {
    std::uint64_t iterations = 0;
};

struct PolynomialRoot {
    double t;
    // Found at a critical point (p' ≈ 0 too) where |p| is within rounding of zero: a double root or a grazing
    // contact, usually without a sign change. The value's sign there cannot be trusted, so it is reported
    // rather than silently dropped; an intersector may ignore it.
    bool tangent = false;
};

// Roots in ascending order, at most one per tolerance width (closer ones are the same root found twice).
class PolynomialRoots {
public:
    int size() const { return count_; }
    bool empty() const { return count_ == 0; }
    const PolynomialRoot& operator[](int i) const { return roots_[i]; }
    const PolynomialRoot* begin() const { return roots_.data(); }
    const PolynomialRoot* end() const { return roots_.data() + count_; }

    // Appends a root not below the last one. Dropped when it duplicates the last root, or when the list is full,
    // which only spurious near-zero detections on a degree-kMaxPolynomialDegree polynomial can cause: the
    // dropped roots are then the farthest ones.
    void add(PolynomialRoot root, const RootTolerance& tolerance) {
        if (count_ > 0 && root.t - roots_[count_ - 1].t <= tolerance.width_at(root.t)) return;
        if (count_ < kMaxPolynomialDegree) roots_[count_++] = root;
    }

private:
    std::array<PolynomialRoot, kMaxPolynomialDegree> roots_{};
    int count_ = 0;
};

}  // namespace isotrace
