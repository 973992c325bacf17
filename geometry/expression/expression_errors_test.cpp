// Bad expressions: every problem is an InputError at the character (file, line, the column of the character in
// the JSON string, its offset in the expression), with a did-you-mean for misspelt names; deep nesting, long
// tapes and constant NaNs are refused, never crashed on.
#include <gtest/gtest.h>

#include <string>

#include "geometry/expression/expression_field.h"
#include "tests/support/input_error_of.h"

namespace isotrace {
namespace {

// The expression's string value starts (its opening quote) at line 7, column 20.
InputError error_of(const std::string& text, const ExpressionNames& names = {}) {
    return testing::input_error_of(
        [&] { compile_expression({text, {"scene.json", 7, 20}, "objects[1].shape.function"}, names); }, text);
}

void expect_error(const std::string& text, std::size_t offset, const std::string& words,
                  const ExpressionNames& names = {}) {
    const InputError error = error_of(text, names);
    EXPECT_EQ(error.location().file, "scene.json") << text;
    EXPECT_EQ(error.location().line, 7) << text;
    EXPECT_EQ(error.location().column, 21 + static_cast<int>(offset)) << text << ": " << error.what();
    EXPECT_EQ(error.field(), "objects[1].shape.function");
    EXPECT_NE(error.problem().find(words), std::string::npos) << text << ": " << error.problem();
    EXPECT_NE(error.problem().find("offset " + std::to_string(offset)), std::string::npos) << error.problem();
}

TEST(ExpressionErrors, SyntaxErrorsPointAtTheCharacter) {
    expect_error("length(p) - ", 12, "expected a number, a name or '(', found the end of the expression");
    expect_error("1 + * 2", 4, "found '*'");
    expect_error("(x + y", 6, "expected ')'");
    expect_error("x y", 2, "expected an operator, found a name \"y\"");
    expect_error("x # 2", 2, "unexpected character '#'");
    expect_error("1e+ 2", 1, "exponent");
    expect_error("1e999", 0, "out of range");
    expect_error("p.w", 2, "expected a component x, y or z");
    expect_error("x.y", 2, "of a number");
    expect_error("min(x,)", 6, "found ')'");
}

TEST(ExpressionErrors, UnknownNamesAndFunctionsSuggestTheNearest) {
    ExpressionNames names;
    names.parameters["radius"] = 1;
    expect_error("length(p) - raduis", 12, "unknown name \"raduis\" (did you mean \"radius\"?)", names);
    expect_error("lenght(p) - 1", 0, "unknown function \"lenght\" (did you mean \"length\"?)");
    expect_error("1 + smoothmin(x, y, 1)", 4, "unknown function \"smoothmin\"");
    expect_error("sin + 1", 0, "\"sin\" is a function");
}

TEST(ExpressionErrors, ArgumentsAreCountedAndTyped) {
    expect_error("x + atan2(y)", 4, "atan2 takes 2 arguments, found 1");
    expect_error("min(x)", 0, "min takes at least 2 arguments, found 1");
    expect_error("fbm(p, 1, 2, 3, 4, 5)", 0, "fbm takes 1 to 5 arguments, found 6");
    expect_error("length(x)", 7, "must be a vector");
    expect_error("vec(p, y, z).x", 4, "must be a number, not a vector");
    expect_error("p", 0, "the expression is a vector");
    expect_error("smin(x, y, z)", 11, "the radius of smin must be a constant");
    expect_error("smin(x, y, -1)", 11, "the radius of smin must be a number in [0");
    expect_error("fbm(p, 2.5)", 7, "the octaves of fbm must be a whole number");
    expect_error("cellular(p, 0.9)", 12, "the jitter of cellular");
}

TEST(ExpressionErrors, ConstantsThatAreNotNumbersAreRefused) {
    expect_error("x + 0/0", 5, "division by zero");
    expect_error("x + 1/(2 - 2)", 5, "division by zero");
    expect_error("x + sqrt(-1)", 4, "square root of a negative number");
    expect_error("x + log(0)", 4, "logarithm");
    expect_error("x + exp(1000)", 4, "overflows");
    ExpressionNames names;
    names.parameters["r"] = std::nan("");
    expect_error("length(p) - r", 12, "the parameter \"r\" is nan, not a finite number", names);
}

TEST(ExpressionErrors, DeepNestingAndLongTapesAreRefused) {
    const std::string deep = std::string(100000, '(') + "x" + std::string(100000, ')');
    EXPECT_NE(std::string(error_of(deep).what()).find("nests deeper than"), std::string::npos);
    EXPECT_NE(std::string(error_of(std::string(100000, '-') + "x").what()).find("nests deeper than"), std::string::npos);
    std::string tower = "x";
    for (int i = 0; i < 100000; ++i) tower += "^2";
    EXPECT_NE(std::string(error_of(tower).what()).find("nests deeper than"), std::string::npos);
    std::string calls;
    for (int i = 0; i < 100000; ++i) calls += "sin(";
    calls += "x";
    EXPECT_NE(std::string(error_of(calls).what()).find("nests deeper than"), std::string::npos);
    // 200 levels are allowed.
    EXPECT_NO_THROW(compile_expression({std::string(199, '(') + "x" + std::string(199, ')'), {}, ""}, {}));
    std::string sum = "x";
    for (int i = 0; i < 1100; ++i) sum += " + sin(" + std::to_string(i) + " * x)";
    expect_error(sum, 0, "more than the limit of 1024");
}

// Each different noise keeps tables of its octaves while the tape is built, before the tape's length is checked:
// the noises are counted as they come, and the one past what a tape can hold is refused where it stands.
TEST(ExpressionErrors, ManyDifferentNoisesAreRefusedAsTheyCome) {
    std::string sum = "fbm(p, 24, 2, 0.5, 0)";
    for (int seed = 1; seed <= 1024; ++seed) sum += " + fbm(p, 24, 2, 0.5, " + std::to_string(seed) + ")";
    const std::size_t last = sum.rfind("fbm");
    expect_error(sum, last, "1024 different noises or more");
    // The same noise many times is one noise.
    std::string same = "fbm(p, 24)";
    for (int i = 0; i < 500; ++i) same += " + fbm(p, 24)";
    EXPECT_NO_THROW(compile_expression({same, {}, ""}, {}));
}

TEST(ExpressionErrors, TheColumnCountsTheEscapesOfTheJsonString) {
    // The tab is written \t in the file: two columns for one character.
    const InputError error = error_of("x\t+ ?");
    EXPECT_EQ(error.location().column, 21 + 4 + 1);
}

TEST(ExpressionErrors, ParsingForFieldTermsReportsSyntaxErrorsToo) {
    const InputError error = testing::input_error_of(
        [] { expression_field_terms({"body(p) +", {"scene.json", 2, 5}, "f"}); }, "field terms");
    EXPECT_EQ(error.location().column, 15);
}

}  // namespace
}  // namespace isotrace
