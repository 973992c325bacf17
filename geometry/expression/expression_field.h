#pragma once
// ExpressionField: an implicit field f(x, y, z) written as text in the expression language of docs/expressions.md
// ("length(p) - r + 0.05*fbm(8*p)"), compiled once to a tape (a flat list of scalar instructions) and evaluated
// four ways: the value, the value with its gradient (forward-mode derivatives), a guaranteed interval of the value
// over a box, and a guaranteed interval of the derivative along a direction over a box (what the crossing search
// needs to prove a stretch of ray monotone).
//
// Use:
//   const ExpressionSource source = expression_source(shape_node, "function");
//   ExpressionNames names;
//   names.parameters = expression_parameters(shape_node, "parameters");
//   for (const std::string& term : expression_field_terms(source)) names.fields[term] = field_of_shape(term);
//   std::shared_ptr<const ExpressionField> field = compile_expression(source, names, container);
//
// Every problem with the text (syntax, unknown names, argument counts, a tape over kMaxExpressionTape, a constant
// part that is NaN) throws InputError at the character: the file, line and column of the JSON string plus the
// offset inside it. Evaluation never yields NaN (docs/expressions.md lists the domain rules), allocates nothing,
// keeps no per-thread state and may run concurrently. A field term calls its field's slope_range with the
// direction its argument moves in, which for body(p) is the direction itself: fields used as terms should read
// slope_range as ∇f · direction.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "renderer/core/input_error.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

class SceneNode;
struct ExpressionTape;

// The text of an expression and where it is written: the location of its JSON string value (the opening quote)
// and the JSON path, for error messages.
struct ExpressionSource {
    std::string text;
    SourceLocation location;
    std::string path;
};

// The names an expression may use besides the built-in ones.
struct ExpressionNames {
    std::map<std::string, double> parameters;  // "r" -> 0.3: a constant
    // "body" -> another shape's field, called as body(p) or body(vec(x, 2*y, z)).
    std::map<std::string, std::shared_ptr<const ImplicitField>> fields;
};

// The longest tape (scalar instructions after constant folding and common-subexpression elimination) an
// expression may compile to: the evaluators keep every slot on the stack (at most 64 bytes a slot).
constexpr int kMaxExpressionTape = 1024;

class ExpressionField final : public ImplicitField {
public:
    ExpressionField(std::shared_ptr<const ExpressionTape> tape, const FieldBox& container);
    ~ExpressionField() override;

    double value(const Vec3d& p) const override;
    Vec3d gradient(const Vec3d& p) const override;
    // Both at once, for the cost of one gradient.
    double value_and_gradient(const Vec3d& p, Vec3d& gradient) const;
    // By forward-mode derivatives along the direction alone (a third of a gradient's derivative work).
    FieldSlope value_and_slope(const Vec3d& p, const Vec3d& direction) const override;
    // The container the caller gave (everything when none).
    FieldBox bounds() const override;
    // False when the value's interval over the cube of half-side `radius` around `centre` excludes 0.
    bool may_reach_surface(const Vec3d& centre, double radius) const override;
    Interval value_range(const IntervalBox& box) const override;
    // The interval of ∇f · direction over the box (direction need not be a unit vector).
    Interval slope_range(const IntervalBox& box, const Vec3d& direction) const override;
    // Both from one run of the tape: value_range's interval (bit for bit) and slope_range's.
    FieldRanges value_and_slope_range(const IntervalBox& box, const Vec3d& direction) const override;
    // The three slope_range intervals along the axes (bit for bit) from one run of the tape.
    IntervalBox gradient_range(const IntervalBox& box) const override;

    // The number of instructions of the compiled tape.
    int tape_length() const;

    // The choices of min, max and |·| that interval arithmetic settles over `box` (tape_pruning.h), and the field
    // whose tape has them made, valid within such a box: equal choices give equal fields.
    std::vector<std::uint8_t> settled_choices(const IntervalBox& box) const;
    std::shared_ptr<const ExpressionField> pruned(const std::vector<std::uint8_t>& choices) const;

private:
    std::shared_ptr<const ExpressionTape> tape_;
    FieldBox container_;
};

// A box holding all of space: the container of an expression whose caller bounds it elsewhere.
FieldBox everywhere_box();

// Parses and compiles `source`; the fields of `names` are kept alive by the result.
std::shared_ptr<const ExpressionField> compile_expression(const ExpressionSource& source, const ExpressionNames& names,
                                                          const FieldBox& container = everywhere_box());

// The names that `source` calls as field terms (called like functions, not built in), each once, in order of first
// use: what the caller must put into ExpressionNames::fields (and check for reference cycles). Throws InputError
// for a syntax error.
std::vector<std::string> expression_field_terms(const ExpressionSource& source);

// The expression string at node[key].
ExpressionSource expression_source(const SceneNode& node, const std::string& key);
// The numbers of the object at node[key] (empty when the key is absent): {"r": 0.3, "k": {"$value": "k"}}.
std::map<std::string, double> expression_parameters(const SceneNode& node, const std::string& key);

}  // namespace isotrace
