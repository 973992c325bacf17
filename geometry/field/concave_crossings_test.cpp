// Tangent cutting planes over concave functions against closed forms: one crossing (a sign change), two around a
// positive maximum, none (both ends outside; a negative maximum, proved by tangents), the first only, kinked
// (piecewise linear) functions, cusps at the ends, and the cases left to the general search (a tangent contact, an
// unknown slope inside, a segment below the resolution).
#include "geometry/field/concave_crossings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace isotrace {
namespace {

struct ValueAndDerivative {
    double value, derivative;
};

struct Answer {
    ConcaveOutcome outcome;
    std::vector<Crossing> crossings;
    CrossingSearchWork work;
};

struct Ends {
    bool cusp_at_t0 = false, cusp_at_t1 = false;
    bool first_only = false;
    double resolution = 1e-9;
};

template <class F>
Answer crossings_of(const F& at, double t0, double t1, Ends ends = {}) {
    Answer answer;
    answer.outcome = visit_concave_crossings<CrossingPrecision::Refined>(
        t0, t1, at(t0).value, at(t1).value, ends.cusp_at_t0, ends.cusp_at_t1, ends.resolution, at, answer.work,
        [&](const Crossing& c) {
            answer.crossings.push_back(c);
            return !ends.first_only;
        });
    return answer;
}

struct Cap {  // lift − (t − a)(t − b): positive between a and b when lift = 0
    double a, b, lift = 0;
    ValueAndDerivative operator()(double t) const { return {lift - (t - a) * (t - b), -(2 * t - a - b)}; }
};

// Settled with these crossings (t to 1e-15, and whether each enters).
void expect_crossings(const Answer& answer, const std::vector<Crossing>& expected) {
    ASSERT_EQ(answer.outcome, ConcaveOutcome::Settled);
    ASSERT_EQ(answer.crossings.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(answer.crossings[i].t, expected[i].t, 1e-15) << i;
        EXPECT_EQ(answer.crossings[i].entering, expected[i].entering) << i;
    }
    EXPECT_EQ(answer.work.crossings, expected.size());
}

TEST(ConcaveCrossings, ACapIsLeftAndEnteredAtItsRoots) {
    // Inside at both ends, outside between 1 and 3: the tangents at the ends meet above zero, g is taken there.
    const Answer answer = crossings_of(Cap{1, 3}, 0, 5);
    expect_crossings(answer, {{1, false}, {3, true}});
    EXPECT_LT(answer.work.evaluations, 20u);
}

TEST(ConcaveCrossings, ASignChangeIsOneCrossingAndFirstOnlyStops) {
    expect_crossings(crossings_of(Cap{1, 3}, 2, 5), {{3, true}});
    expect_crossings(crossings_of(Cap{1, 3}, 0, 2), {{1, false}});
    const Answer first = crossings_of(Cap{1, 3}, 0, 5, {.first_only = true});
    EXPECT_EQ(first.outcome, ConcaveOutcome::Stopped);
    ASSERT_EQ(first.crossings.size(), 1u);
    EXPECT_NEAR(first.crossings[0].t, 1, 1e-15);
}

TEST(ConcaveCrossings, MissesAreProvedWithoutCrossings) {
    expect_crossings(crossings_of(Cap{1, 3}, 1.5, 2.5), {});  // outside throughout
    const Answer below = crossings_of(Cap{1, 3, -1.5}, 0, 5);  // maximum −0.5 at t = 2
    expect_crossings(below, {});
    EXPECT_LT(below.work.evaluations, 12u);
    const Answer falling = crossings_of(Cap{-3, -1}, 0, 5);  // falling from the start: the maximum is there
    expect_crossings(falling, {});
    EXPECT_EQ(falling.work.evaluations, 2u);  // the two end slopes
}

TEST(ConcaveCrossings, KinkedFunctionsAreSolvedExactly) {
    // 0.5 − |t − 2| and min(t − 1, 5 − 2t): piecewise linear, concave.
    const auto tent = [](double t) { return ValueAndDerivative{0.5 - std::abs(t - 2), t < 2 ? 1.0 : -1.0}; };
    expect_crossings(crossings_of(tent, 0, 4), {{1.5, false}, {2.5, true}});
    const auto roof = [](double t) {
        return t - 1 < 5 - 2 * t ? ValueAndDerivative{t - 1, 1} : ValueAndDerivative{5 - 2 * t, -2};
    };
    expect_crossings(crossings_of(roof, -1, 4), {{1, false}, {2.5, true}});
}

TEST(ConcaveCrossings, CuspsAtTheEndsGiveNoTangent) {
    // 0.3·(√t + √(4 − t)) − 0.651 has unbounded slopes at both ends; a cusp end's slope is not asked for, and a
    // wrong one there (the other side's, as rounding can give at a coordinate plane) must not be believed.
    const auto cusp = [](double t) {
        const double a = std::sqrt(std::max(t, 0.0)), b = std::sqrt(std::max(4 - t, 0.0));
        const double slope = t <= 0 ? -1e300 : t >= 4 ? 1e300 : 0.15 / a - 0.15 / b;  // wrong signs at the ends
        return ValueAndDerivative{0.3 * (a + b) - 0.651, slope};
    };
    const Answer answer = crossings_of(cusp, 0, 4, {.cusp_at_t0 = true, .cusp_at_t1 = true});
    ASSERT_EQ(answer.outcome, ConcaveOutcome::Settled);
    ASSERT_EQ(answer.crossings.size(), 2u);  // 0.3(√t + √(4 − t)) reaches 0.849 at t = 2
    EXPECT_FALSE(answer.crossings[0].entering);
    EXPECT_NEAR(cusp(answer.crossings[0].t).value, 0, 1e-12);
    // Believed, the ends' slopes would have proved a miss.
    EXPECT_TRUE(crossings_of(cusp, 0, 4).crossings.empty());
}

TEST(ConcaveCrossings, TangentContactsUnknownSlopesAndNarrowSegmentsAreLeftToTheGeneralSearch) {
    // −(t − 2)²: a double root; the tangents close in on it without settling.
    const Answer tangent = crossings_of(Cap{2, 2}, 0, 5);
    EXPECT_EQ(tangent.outcome, ConcaveOutcome::Unsettled);
    EXPECT_TRUE(tangent.crossings.empty());
    const auto unknown = [](double t) { return ValueAndDerivative{-(t - 1) * (t - 3) - 2, NAN}; };
    EXPECT_EQ(crossings_of(unknown, 0, 5).outcome, ConcaveOutcome::Unsettled);
    EXPECT_EQ(crossings_of(Cap{1, 3}, 0, 5, {.resolution = 10}).outcome, ConcaveOutcome::Unsettled);
}

}  // namespace
}  // namespace isotrace
