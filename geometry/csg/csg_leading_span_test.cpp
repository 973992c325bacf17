// A union's leading span: its entry bit for bit the first span's of the full combination, its exit no later, and
// operands whose bounds the ray reaches only beyond that entry left unasked.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "geometry/csg/csg_test_support.h"

namespace isotrace::csg_test {
namespace {

TEST(CsgLeadingSpan, OpensWithTheFullCombinationsFirstSpanAndEndsNoLater) {
    std::vector<std::unique_ptr<CsgShape>> unions;
    unions.push_back(csg(CsgOperation::Union, child(sphere({0, 0, 0}, 1)), child(sphere({1.2, 0, 0}, 0.5))));
    // Overlapping, touching and nested operands; a box sharing a face with another.
    unions.push_back(csg(CsgOperation::Union, child(box({0, 0, 0}, {0.5, 0.5, 0.5})), child(box({1, 0, 0}, {0.5, 0.5, 0.5})),
                         child(sphere({0, 1.5, 0}, 0.4))));
    unions.push_back(csg(CsgOperation::Union, child(sphere({0, 0, 0}, 1)),
                         child(csg(CsgOperation::Difference, child(box({1, 0, 0}, {0.5, 0.5, 0.5})),
                                   child(sphere({1.5, 0, 0}, 0.3)))),
                         child(sphere({-2, 0, 0}, 0.5), Transform::translate({0, 0.5, 0}))));
    std::mt19937 random(5);
    std::uniform_real_distribution<double> coordinate(-3, 3), unit(-1, 1), near(0, 1);
    int found = 0;
    for (std::size_t k = 0; k < unions.size(); ++k)
        for (int i = 0; i < 4000; ++i) {
            const Vec3d origin(coordinate(random), coordinate(random), coordinate(random));
            const Vec3d direction = i % 2 == 0 ? Vec3d(unit(random), unit(random), unit(random)) : origin * -0.4;
            const double t_min = i % 3 == 0 ? near(random) : 0;
            QueryScratch scratch;
            std::vector<InsideSpan> spans;
            unions[k]->inside_spans(origin, direction, t_min, 1e30, spans, scratch);
            const LeadingSpan lead = unions[k]->leading_span(origin, direction, t_min, 1e30, scratch);
            const std::string what = "union " + std::to_string(k) + " ray " + std::to_string(i);
            if (lead.outcome == LeadingSpan::Outcome::None) { EXPECT_TRUE(spans.empty()) << what; }
            if (!lead.found()) continue;
            ++found;
            ASSERT_FALSE(spans.empty()) << what;
            EXPECT_EQ(lead.span.enter.t, spans.front().enter.t) << what;
            EXPECT_EQ(lead.span.enter.normal, spans.front().enter.normal) << what;
            EXPECT_EQ(lead.span.enter.primitive, spans.front().enter.primitive) << what;
            EXPECT_EQ(lead.span.enter.part, spans.front().enter.part) << what;
            EXPECT_LE(lead.span.exit.t, spans.front().exit.t) << what;
        }
    EXPECT_GT(found, 3000);
}

TEST(CsgLeadingSpan, LeavesOperandsUnaskedThatBeginBeyondTheEntry) {
    auto far_ball = std::make_unique<CountingBall>(Vec3d(3, 0, 0), 0.5);
    const CountingBall& counting = *far_ball;
    const auto tree = csg(CsgOperation::Difference,
                          child(csg(CsgOperation::Union, child(sphere({0, 0, 0}, 1)), child(std::move(far_ball)))),
                          child(sphere({0, 0, 5}, 0.5)));
    QueryScratch scratch;
    const auto hit = tree->first_surface_point({-3, 0, 0}, {1, 0, 0}, 0, 1e30, scratch);
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->t, 2);
    EXPECT_EQ(counting.queries, 0);
    // A ray that reaches the far ball first asks it.
    const auto back = tree->first_surface_point({6, 0, 0}, {-1, 0, 0}, 0, 1e30, scratch);
    ASSERT_TRUE(back);
    EXPECT_DOUBLE_EQ(back->t, 2.5);
    EXPECT_EQ(counting.queries, 1);
}

// A leading span that settles nothing (the subtracted ball does not claim to stay clear of the entry) is followed by
// the union's full spans, which take the spans the leading span asked for instead of asking again.
TEST(CsgLeadingSpan, TheFullSpansAfterItDoNotAskAgain) {
    auto near_ball = std::make_unique<CountingBall>(Vec3d(0, 0, 0), 1);
    const CountingBall& counting = *near_ball;
    const auto tree = csg(CsgOperation::Difference,
                          child(csg(CsgOperation::Union, child(std::move(near_ball)), child(sphere({3, 0, 0}, 0.5)))),
                          child(std::make_unique<CountingBall>(Vec3d(0, 0, 5), 0.5)));
    QueryScratch scratch;
    const auto hit = tree->first_surface_point({-3, 0, 0}, {1, 0, 0}, 0, 1e30, scratch);
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->t, 2);
    EXPECT_EQ(counting.queries, 1);
}

}  // namespace
}  // namespace isotrace::csg_test
