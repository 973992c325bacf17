// Roth's classification on hand-made span lists: each operator, the normal flip of subtracted operands, cut
// ends, and the coincident-surface policy (simultaneous events within kCoincidentRelative).
#include <gtest/gtest.h>

#include <vector>

#include "geometry/csg/span_combination.h"

namespace isotrace {
namespace {

// A span from a to b along +x: outward normals -x at the entry and +x at the exit; primitive names the solid.
InsideSpan span(double a, double b, std::uint32_t primitive) {
    return {{a, {-1, 0, 0}, primitive, 0}, {b, {1, 0, 0}, primitive, 0}};
}

std::vector<InsideSpan> combine(CsgOperation operation, const std::vector<std::vector<InsideSpan>>& operands) {
    std::vector<SpanEvent> events;
    for (std::uint32_t i = 0; i < operands.size(); ++i) append_span_events(i, 10 * i, operands[i], events);
    std::vector<InsideSpan> result;
    combine_span_events(operation, std::uint32_t(operands.size()), events, result);
    return result;
}

// [enter t, exit t] pairs of a span list, for compact expectations.
std::vector<std::pair<double, double>> ends(const std::vector<InsideSpan>& spans) {
    std::vector<std::pair<double, double>> result;
    for (const InsideSpan& s : spans) result.emplace_back(s.enter.t, s.exit.t);
    return result;
}

using Ends = std::vector<std::pair<double, double>>;

TEST(CsgSpanCombination, UnionIntersectionDifferenceOfOverlappingSpans) {
    const std::vector<InsideSpan> a = {span(0, 2, 1), span(5, 6, 1)}, b = {span(1, 3, 2), span(4, 4.5, 2)};
    EXPECT_EQ(ends(combine(CsgOperation::Union, {a, b})), (Ends{{0, 3}, {4, 4.5}, {5, 6}}));
    EXPECT_EQ(ends(combine(CsgOperation::Intersection, {a, b})), (Ends{{1, 2}}));
    EXPECT_EQ(ends(combine(CsgOperation::Difference, {a, b})), (Ends{{0, 1}, {5, 6}}));
    EXPECT_EQ(ends(combine(CsgOperation::Difference, {b, a})), (Ends{{2, 3}, {4, 4.5}}));
}

TEST(CsgSpanCombination, EndsComeFromTheOperandThatBoundsTheResultWithSubtractedNormalsFlipped) {
    const auto result = combine(CsgOperation::Difference, {{span(0, 2, 1)}, {span(1, 3, 2)}});
    ASSERT_EQ(result.size(), 1u);
    EXPECT_EQ(result[0].enter.primitive, 1u);
    EXPECT_EQ(result[0].enter.normal, Vec3d(-1, 0, 0));
    EXPECT_EQ(result[0].exit.primitive, 2u);
    EXPECT_EQ(result[0].exit.part, 10u);  // the second operand's parts start at 10 here
    EXPECT_EQ(result[0].exit.normal, Vec3d(1, 0, 0)) << "B's entry normal -x, flipped: the result's outward side";
}

TEST(CsgSpanCombination, NaryOperatorsAndDifferenceSubtractsAllButTheFirst) {
    const std::vector<InsideSpan> a = {span(0, 10, 1)}, b = {span(1, 2, 2)}, c = {span(5, 12, 3)};
    EXPECT_EQ(ends(combine(CsgOperation::Difference, {a, b, c})), (Ends{{0, 1}, {2, 5}}));
    EXPECT_EQ(ends(combine(CsgOperation::Intersection, {a, {span(1, 8, 2)}, c})), (Ends{{5, 8}}));
    EXPECT_EQ(ends(combine(CsgOperation::Union, {b, a, c})), (Ends{{0, 12}}));
    EXPECT_TRUE(combine(CsgOperation::Intersection, {a, b, c}).empty());
}

TEST(CsgSpanCombination, CoincidentSurfacesFollowThePolicy) {
    const std::vector<InsideSpan> a = {span(1, 3, 1)};
    EXPECT_TRUE(combine(CsgOperation::Difference, {a, a}).empty()) << "A - A";
    EXPECT_EQ(ends(combine(CsgOperation::Union, {a, a})), (Ends{{1, 3}})) << "A u A";
    EXPECT_EQ(ends(combine(CsgOperation::Intersection, {a, a})), (Ends{{1, 3}})) << "A n A";
    // The same surfaces computed by different code differ in the last bits: still simultaneous.
    const std::vector<InsideSpan> a_again = {span(1 + 4e-16, 3 - 4e-16, 2)};
    EXPECT_TRUE(combine(CsgOperation::Difference, {a, a_again}).empty());
    // Touching solids of a union merge: no boundary where one ends and the other begins.
    EXPECT_EQ(ends(combine(CsgOperation::Union, {a, {span(3, 5, 2)}})), (Ends{{1, 5}}));
    EXPECT_EQ(ends(combine(CsgOperation::Union, {a, {span(3 + 1e-15, 5, 2)}})), (Ends{{1, 5}}));
    // A real gap stays, however thin: 1e-6 relative is far above the coincidence tolerance.
    EXPECT_EQ(ends(combine(CsgOperation::Union, {a, {span(3 + 3e-6, 5, 2)}})), (Ends{{1, 3}, {3 + 3e-6, 5}}));
    // Touching solids have no common interior; a face shared by A and a subtracted B leaves A's other part.
    EXPECT_TRUE(combine(CsgOperation::Intersection, {a, {span(3, 5, 2)}}).empty());
    EXPECT_EQ(ends(combine(CsgOperation::Difference, {a, {span(2, 3, 2)}})), (Ends{{1, 2}}));
}

TEST(CsgSpanCombination, CutEndsStayCuts) {
    InsideSpan clipped = span(0, 4, 1);
    clipped.enter.primitive = BoundaryPoint::kCut;  // the ray starts inside A
    const auto result = combine(CsgOperation::Difference, {{clipped}, {span(2, 3, 2)}});
    ASSERT_EQ(result.size(), 2u);
    EXPECT_FALSE(result[0].enter.on_surface());
    EXPECT_TRUE(result[0].exit.on_surface());
    EXPECT_TRUE(result[1].enter.on_surface());
}

// CSG queries a later operand over the first one's span widened by the tolerance, so the later one can start with
// a cut a hair before the first one's surface. The surface bounds the result, not the cut that sorts before it.
TEST(CsgSpanCombination, ASurfaceSimultaneousWithACutBoundsTheResult) {
    const double t = 5, hair = 0.5 * kCoincidentRelative * t;
    InsideSpan widened = span(t - hair, 7 + hair, 2);
    widened.enter.primitive = widened.exit.primitive = BoundaryPoint::kCut;
    const auto result = combine(CsgOperation::Intersection, {{span(t, 7, 1)}, {widened}});
    ASSERT_EQ(result.size(), 1u);
    EXPECT_TRUE(result[0].enter.on_surface());
    EXPECT_EQ(result[0].enter.primitive, 1u);
    EXPECT_TRUE(result[0].exit.on_surface());
    EXPECT_EQ(result[0].exit.primitive, 1u);
}

}  // namespace
}  // namespace isotrace
