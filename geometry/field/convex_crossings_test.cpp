// The Newton marches over convex functions against closed forms: two crossings, one from inside, none (a positive
// minimum, a root beyond the end), the first only, kinked (piecewise linear) functions, and the cases left to the
// general search (a tangent contact, an unknown derivative).
#include "geometry/field/convex_crossings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace isotrace {
namespace {

struct ValueAndDerivative {
    double value, derivative;
};

struct Answer {
    bool settled;
    std::vector<Crossing> crossings;
    CrossingSearchWork work;
};

template <class F>
Answer crossings_of(const F& at, double t0, double t1, bool first_only = false) {
    Answer answer;
    answer.settled = visit_convex_crossings(t0, t1, at, first_only, answer.work, [&](const Crossing& c) {
        answer.crossings.push_back(c);
        return true;
    });
    return answer;
}

struct Parabola {  // (t − a)(t − b) + lift
    double a, b, lift = 0;
    ValueAndDerivative operator()(double t) const { return {(t - a) * (t - b) + lift, 2 * t - a - b}; }
};

// The answer settled with these crossings (t to 1e-15, and whether each enters).
void expect_crossings(const Answer& answer, const std::vector<Crossing>& expected) {
    ASSERT_TRUE(answer.settled);
    ASSERT_EQ(answer.crossings.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(answer.crossings[i].t, expected[i].t, 1e-15) << i;
        EXPECT_EQ(answer.crossings[i].entering, expected[i].entering) << i;
    }
    EXPECT_EQ(answer.work.crossings, expected.size());
}

TEST(ConvexCrossings, AParabolaIsEnteredAndLeftAtItsRoots) {
    const Answer answer = crossings_of(Parabola{1, 3}, 0, 5);
    expect_crossings(answer, {{1, true}, {3, false}});
    EXPECT_LT(answer.work.evaluations, 16u);
}

TEST(ConvexCrossings, FromInsideOnlyTheExitAndFirstOnlyStopsAtTheEntry) {
    expect_crossings(crossings_of(Parabola{1, 3}, 2, 5), {{3, false}});
    expect_crossings(crossings_of(Parabola{1, 3}, 0, 5, true), {{1, true}});
    expect_crossings(crossings_of(Parabola{1, 3}, 0, 2), {{1, true}});
    expect_crossings(crossings_of(Parabola{1, 3}, 1.5, 2.5), {});  // inside throughout
}

TEST(ConvexCrossings, MissesAreProvedWithoutCrossings) {
    expect_crossings(crossings_of(Parabola{1, 3, 1.5}, 0, 5), {});  // minimum 0.5 at t = 2
    expect_crossings(crossings_of(Parabola{7, 9}, 0, 5), {});       // roots beyond the end
    const Answer rising = crossings_of(Parabola{-3, -1}, 0, 5);     // rising from the start
    expect_crossings(rising, {});
    EXPECT_EQ(rising.work.evaluations, 1u);  // the start's sample settles it; the end is not taken
}

TEST(ConvexCrossings, TheFirstCrossingFromOutsideDoesNotTakeTheEnd) {
    int end_samples = 0;
    const auto at = [&](double t) {
        if (t == 5) ++end_samples;
        return Parabola{1, 3}(t);
    };
    expect_crossings(crossings_of(at, 0, 5, true), {{1, true}});
    EXPECT_EQ(end_samples, 0);
    expect_crossings(crossings_of(at, 0, 5), {{1, true}, {3, false}});
    EXPECT_EQ(end_samples, 1);
}

TEST(ConvexCrossings, KinkedFunctionsAreSolvedExactly) {
    // |t − 2| − 0.5 and max(1 − t, 2t − 5): piecewise linear, convex.
    const auto v = [](double t) { return ValueAndDerivative{std::abs(t - 2) - 0.5, t < 2 ? -1.0 : 1.0}; };
    expect_crossings(crossings_of(v, 0, 4), {{1.5, true}, {2.5, false}});
    const auto ramp = [](double t) {
        return 1 - t > 2 * t - 5 ? ValueAndDerivative{1 - t, -1} : ValueAndDerivative{2 * t - 5, 2};
    };
    expect_crossings(crossings_of(ramp, -1, 4), {{1, true}, {2.5, false}});
}

TEST(ConvexCrossings, TangentContactsAndUnknownSlopesAreLeftToTheGeneralSearch) {
    // (t − 2)²: a double root; Newton halves the distance each step and gives up.
    EXPECT_FALSE(crossings_of(Parabola{2, 2}, 0, 5).settled);
    const auto unknown = [](double t) { return ValueAndDerivative{(t - 1) * (t - 3), NAN}; };
    const Answer answer = crossings_of(unknown, 0, 5);
    EXPECT_FALSE(answer.settled);
    EXPECT_TRUE(answer.crossings.empty());
}

}  // namespace
}  // namespace isotrace
