#include "geometry/expression/expression_field.h"

#include <limits>

#include "geometry/expression/expression_compiler.h"
#include "geometry/expression/expression_evaluator.h"
#include "geometry/expression/tape_pruning.h"
#include "renderer/params/scene_node.h"

namespace isotrace {
namespace {

using expression_math::IntervalSlope;
using expression_math::PointGradient;
using expression_math::PointSlope;

// The column of the character at `offset` of a JSON string's decoded text, counting the escapes that wrote the
// characters a JSON string cannot hold as they are (a quote, a backslash, control characters).
int column_in_file(const std::string& text, std::size_t offset, int string_column) {
    int column = string_column + 1;  // past the opening quote
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        const bool short_escape = c == '"' || c == '\\' || c == '\b' || c == '\f' || c == '\n' || c == '\r' || c == '\t';
        column += short_escape ? 2 : (c < 0x20 ? 6 : 1);
    }
    return column;
}

[[noreturn]] void throw_at(const ExpressionSource& source, const ExpressionError& error) {
    SourceLocation where = source.location;
    if (where.column > 0) where.column = column_in_file(source.text, error.offset, where.column);
    throw InputError(where, source.path,
                     error.problem + " (at offset " + std::to_string(error.offset) + " of the expression)");
}

}  // namespace

ExpressionField::ExpressionField(std::shared_ptr<const ExpressionTape> tape, const FieldBox& container)
    : tape_(std::move(tape)), container_(container) {}

ExpressionField::~ExpressionField() = default;

double ExpressionField::value(const Vec3d& p) const {
    return expression_math::run<double>(*tape_, p.x, p.y, p.z);
}

double ExpressionField::value_and_gradient(const Vec3d& p, Vec3d& gradient) const {
    const PointGradient result = expression_math::run<PointGradient>(
        *tape_, {p.x, {1, 0, 0}}, {p.y, {0, 1, 0}}, {p.z, {0, 0, 1}});
    gradient = result.d;
    return result.v;
}

FieldSlope ExpressionField::value_and_slope(const Vec3d& p, const Vec3d& direction) const {
    const PointSlope result =
        expression_math::run<PointSlope>(*tape_, {p.x, direction.x}, {p.y, direction.y}, {p.z, direction.z});
    return {result.v, result.d};
}

Vec3d ExpressionField::gradient(const Vec3d& p) const {
    Vec3d g;
    value_and_gradient(p, g);
    return g;
}

FieldBox ExpressionField::bounds() const { return container_; }

bool ExpressionField::may_reach_surface(const Vec3d& centre, double radius) const {
    IntervalBox box{{centre.x - radius, centre.x + radius},
                    {centre.y - radius, centre.y + radius},
                    {centre.z - radius, centre.z + radius}};
    if (!clip_box(box, {{container_.lower.x, container_.upper.x},
                        {container_.lower.y, container_.upper.y},
                        {container_.lower.z, container_.upper.z}}))
        return false;
    return !value_range(box).excludes_zero();
}

Interval ExpressionField::value_range(const IntervalBox& box) const {
    return expression_math::run<Interval>(*tape_, box.x, box.y, box.z);
}

Interval ExpressionField::slope_range(const IntervalBox& box, const Vec3d& direction) const {
    return value_and_slope_range(box, direction).slope;
}

FieldRanges ExpressionField::value_and_slope_range(const IntervalBox& box, const Vec3d& direction) const {
    const IntervalSlope result = expression_math::run<IntervalSlope>(*tape_, {box.x, Interval::point(direction.x)},
                                                                     {box.y, Interval::point(direction.y)},
                                                                     {box.z, Interval::point(direction.z)});
    return {result.v, result.d};
}

IntervalBox ExpressionField::gradient_range(const IntervalBox& box) const {
    using expression_math::IntervalGradient;
    const Interval one = Interval::point(1), zero = Interval::point(0);
    const IntervalGradient result = expression_math::run<IntervalGradient>(
        *tape_, {box.x, {one, zero, zero}}, {box.y, {zero, one, zero}}, {box.z, {zero, zero, one}});
    return {result.d.x, result.d.y, result.d.z};
}

int ExpressionField::tape_length() const { return static_cast<int>(tape_->code.size()); }

std::vector<std::uint8_t> ExpressionField::settled_choices(const IntervalBox& box) const {
    return isotrace::settled_choices(*tape_, box);
}

std::shared_ptr<const ExpressionField> ExpressionField::pruned(const std::vector<std::uint8_t>& choices) const {
    return std::make_shared<const ExpressionField>(std::make_shared<const ExpressionTape>(pruned_tape(*tape_, choices)),
                                                   container_);
}

FieldBox everywhere_box() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {{-inf, -inf, -inf}, {inf, inf, inf}};
}

std::shared_ptr<const ExpressionField> compile_expression(const ExpressionSource& source, const ExpressionNames& names,
                                                          const FieldBox& container) {
    try {
        CompiledExpression compiled = compile_expression_text(source.text, &names);
        const std::size_t length = compiled.tape.code.size();
        if (length > static_cast<std::size_t>(kMaxExpressionTape))
            throw ExpressionError{0, "the expression compiles to " + std::to_string(length) +
                                         " instructions, more than the limit of " + std::to_string(kMaxExpressionTape)};
        return std::make_shared<const ExpressionField>(
            std::make_shared<const ExpressionTape>(std::move(compiled.tape)), container);
    } catch (const ExpressionError& error) {
        throw_at(source, error);
    }
}

std::vector<std::string> expression_field_terms(const ExpressionSource& source) {
    try {
        return compile_expression_text(source.text, nullptr).field_terms;
    } catch (const ExpressionError& error) {
        throw_at(source, error);
    }
}

ExpressionSource expression_source(const SceneNode& node, const std::string& key) {
    const std::string text = node.string(key);
    return {text, node.json().find(key)->location, node.child_path(key)};
}

std::map<std::string, double> expression_parameters(const SceneNode& node, const std::string& key) {
    std::map<std::string, double> parameters;
    const std::optional<SceneNode> object = node.optional_object(key);
    if (!object) return parameters;
    for (const std::string& name : object->keys()) {
        if (is_builtin_name(name))
            object->fail_at(name, "the parameter \"" + name + "\" has the name of a built-in of the expression language");
        parameters[name] = object->number(name);
    }
    return parameters;
}

}  // namespace isotrace
