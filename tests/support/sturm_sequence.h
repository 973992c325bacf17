#pragma once
// Sturm sequences (p, p', −rem(p, p'), ...): the number of sign changes of the sequence drops by one at each
// distinct real root, which counts and isolates roots exactly up to rounding. Slower than the monotone-interval
// finder, so it serves as the test oracle of the root finders and of the blob march (blob_stress_test.cpp).
#include <array>

#include "geometry/polynomial/polynomial.h"
#include "geometry/polynomial/polynomial_root.h"

namespace isotrace {

class SturmSequence {
public:
    // Every member is normalised (exact power-of-two scaling) so long sequences neither overflow nor underflow.
    // A remainder that is cancellation noise ends the sequence; a non-constant last member is then g = gcd(p, p')
    // and every member is divided by it, which leaves the Sturm sequence of the square-free part p/g: the counts
    // below are of distinct roots, multiple roots counted once, and are right even at a multiple root.
    explicit SturmSequence(const Polynomial& p);

    int size() const { return size_; }
    // The first member: p without repeated factors (up to a positive scale). All its roots are simple.
    const Polynomial& square_free_part() const { return members_[0]; }
    // gcd(p, p') (normalised): the constant 1 when every root of p is simple; otherwise it vanishes exactly at
    // the multiple roots.
    const Polynomial& repeated_factors() const { return repeated_factors_; }
    const Polynomial& operator[](int i) const { return members_[i]; }
    // Sign changes of the sequence at t, zero members skipped.
    int sign_changes_at(double t) const;
    // Distinct real roots in the half-open interval (a, b].
    int count_roots(double a, double b) const { return sign_changes_at(a) - sign_changes_at(b); }

private:
    std::array<Polynomial, kMaxPolynomialDegree + 1> members_;
    Polynomial repeated_factors_{1};
    int size_ = 0;
};

// All distinct roots in the closed interval [a, b] by Sturm bisection, each refined in its isolating bracket.
// Leading terms negligible on [a, b] are dropped first. An end whose value is within rounding of zero is a root.
// Each isolated root is refined on the square-free part, so double roots are as accurate as the gcd; a root of
// multiplicity > 1 (a root of the repeated factors) is marked tangent, like the monotone finder's. A cluster the tolerance cannot separate is
// reported once. The zero polynomial reports no roots.
PolynomialRoots sturm_roots(const Polynomial& p, double a, double b, const RootTolerance& tolerance = {});

}  // namespace isotrace
