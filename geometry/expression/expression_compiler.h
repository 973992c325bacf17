#pragma once
// The parser of the expression language (grammar in docs/expressions.md) and its translation to a tape: vectors
// become three scalar slots, the smooth operations and the functions defined by others (mix, clamp, length, …)
// become their formulas, and integer powers become multiplications.
#include <string>
#include <string_view>
#include <vector>

#include "geometry/expression/expression_field.h"
#include "geometry/expression/expression_lexer.h"
#include "geometry/expression/expression_tape.h"

namespace isotrace {

struct CompiledExpression {
    ExpressionTape tape;
    std::vector<std::string> field_terms;  // the names called as field terms, in order of first use
};

// Throws ExpressionError. Without `names` the text is only parsed (for its field terms): unknown names read as
// parameters, unknown calls as field terms, and constants are not checked.
CompiledExpression compile_expression_text(std::string_view text, const ExpressionNames* names);

// Whether a parameter may not be called `name` because the language uses it (p, x, pi, sin, …).
bool is_builtin_name(const std::string& name);

// Expressions nest at most this deep (parentheses, calls, operators): the parser recurses once per level.
constexpr int kMaxExpressionNesting = 200;

}  // namespace isotrace
