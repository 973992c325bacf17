// Expressions read from a scene file: an error points at the character's own column in the file (escapes
// counted), parameters are read as numbers and may not take a built-in's name.
#include <gtest/gtest.h>

#include "geometry/expression/expression_field.h"
#include "renderer/params/json_document.h"
#include "renderer/params/scene_node.h"
#include "tests/support/input_error_of.h"

namespace isotrace {
namespace {

// The column (1-based) of `needle` in the one-line `json`.
int column_of(const std::string& json, const std::string& needle) { return static_cast<int>(json.find(needle)) + 1; }

InputError error_in(const std::string& json) {
    const JsonValue document = parse_json(json, "scene.json");
    const SceneNode shape(document, "shape", std::make_shared<SceneFileContext>());
    return testing::input_error_of(
        [&] {
            ExpressionNames names;
            names.parameters = expression_parameters(shape, "parameters");
            compile_expression(expression_source(shape, "function"), names);
        },
        json);
}

TEST(ExpressionScene, ErrorsPointAtTheCharacterInTheFile) {
    const std::string json = R"({"type": "isosurface", "function": "length(p) - rr", "parameters": {"r": 0.3}})";
    const InputError error = error_in(json);
    EXPECT_EQ(error.location().file, "scene.json");
    EXPECT_EQ(error.location().line, 1);
    EXPECT_EQ(error.location().column, column_of(json, "rr"));
    EXPECT_EQ(error.field(), "shape.function");
    EXPECT_NE(error.problem().find("unknown name \"rr\" (did you mean \"r\"?)"), std::string::npos) << error.what();
}

TEST(ExpressionScene, EscapesBeforeTheCharacterCountAsWritten) {
    const std::string json = R"({"function": "x\t+\n y +", "parameters": {}})";
    EXPECT_EQ(error_in(json).location().column, column_of(json, "\",") );  // the end of the expression
}

TEST(ExpressionScene, ParametersAreNumbersWithoutBuiltInNames) {
    const std::string json = R"({"function": "x", "parameters": {"pi": 3}})";
    const InputError error = error_in(json);
    EXPECT_EQ(error.field(), "shape.parameters.pi");
    EXPECT_NE(error.problem().find("built-in"), std::string::npos);
    EXPECT_NE(std::string(error_in(R"({"function": "x", "parameters": {"r": "big"}})").what()).find("expected a number"),
              std::string::npos);
    const JsonValue document = parse_json(R"({"function": "k * x", "parameters": {"k": 2}})", "scene.json");
    const SceneNode shape(document, "shape", std::make_shared<SceneFileContext>());
    ExpressionNames names;
    names.parameters = expression_parameters(shape, "parameters");
    EXPECT_EQ(compile_expression(expression_source(shape, "function"), names)->value({3, 0, 0}), 6);
}

}  // namespace
}  // namespace isotrace
