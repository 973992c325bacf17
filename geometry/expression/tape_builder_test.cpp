// TapeBuilder: what it tells of a slot stays true while the tape grows.
#include "geometry/expression/tape_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "geometry/expression/expression_field.h"

namespace isotrace {
namespace {

// A constant's value is handed out as a copy: emitting moves the tape, and a pointer into it, read after the next
// instructions were emitted (a negative whole exponent's sign, after its power's multiplications), read freed memory.
TEST(TapeBuilder, AConstantsValueOutlivesTheTapeGrowing) {
    TapeBuilder builder(true);
    const int slot = builder.constant(-3);
    const std::optional<double> value = builder.constant_value(slot);
    const int x = builder.emit({Op::X}, 0);
    for (int k = 0; k < 1000; ++k) builder.binary(Op::Add, x, builder.constant(k + 0.5), 0);  // reallocates
    ASSERT_TRUE(value.has_value());
    EXPECT_EQ(*value, -3);
    EXPECT_EQ(builder.constant_value(slot), -3);
    EXPECT_FALSE(builder.constant_value(x).has_value());
}

// The case that read freed memory: whole negative exponents, each emitting its power before the reciprocal.
TEST(TapeBuilder, NegativeWholeExponentsAreReciprocalPowers) {
    const std::shared_ptr<const ExpressionField> field =
        compile_expression({"x^-1 + x^-2 + y^-3 + (x + y)^-5 + z^-7", {"scene.json", 1, 1}, "f"}, {});
    const Vec3d p{1.5, -0.75, 1.25};
    const double expected = 1 / p.x + 1 / (p.x * p.x) + 1 / (p.y * p.y * p.y) + 1 / std::pow(p.x + p.y, 5) +
                            1 / std::pow(p.z, 7);
    EXPECT_NEAR(field->value(p), expected, 1e-12 * std::abs(expected));
}

}  // namespace
}  // namespace isotrace
