#include "geometry/expression/expression_compiler.h"

#include <cmath>
#include <functional>
#include <numbers>

#include "geometry/expression/tape_builder.h"
#include "renderer/core/did_you_mean.h"

namespace isotrace {
namespace {

enum class Builtin {
    Abs, Sqrt, Exp, Log, Sin, Cos, Tan, Atan, Atan2, Min, Max, Clamp, Mix, Smin, Smax, Sdiff, Length, Dot, Vec,
    Noise, Simplex, Fbm, Turbulence, Cellular,
};

struct FunctionInfo {
    const char* name;
    Builtin builtin;
    int min_arguments, max_arguments;  // max −1: any number
};

constexpr FunctionInfo kFunctions[] = {
    {"abs", Builtin::Abs, 1, 1},          {"sqrt", Builtin::Sqrt, 1, 1},
    {"exp", Builtin::Exp, 1, 1},          {"log", Builtin::Log, 1, 1},
    {"sin", Builtin::Sin, 1, 1},          {"cos", Builtin::Cos, 1, 1},
    {"tan", Builtin::Tan, 1, 1},          {"atan", Builtin::Atan, 1, 1},
    {"atan2", Builtin::Atan2, 2, 2},      {"min", Builtin::Min, 2, -1},
    {"max", Builtin::Max, 2, -1},         {"clamp", Builtin::Clamp, 3, 3},
    {"mix", Builtin::Mix, 3, 3},          {"smin", Builtin::Smin, 3, 3},
    {"smax", Builtin::Smax, 3, 3},        {"sdiff", Builtin::Sdiff, 3, 3},
    {"length", Builtin::Length, 1, 1},    {"dot", Builtin::Dot, 2, 2},
    {"vec", Builtin::Vec, 3, 3},          {"noise", Builtin::Noise, 1, 2},
    {"simplex", Builtin::Simplex, 1, 2},  {"fbm", Builtin::Fbm, 1, 5},
    {"turbulence", Builtin::Turbulence, 1, 5}, {"cellular", Builtin::Cellular, 1, 3},
};

constexpr const char* kNames[] = {"p", "x", "y", "z", "pi", "e"};

const FunctionInfo* find_function(std::string_view name) {
    for (const FunctionInfo& f : kFunctions)
        if (name == f.name) return &f;
    return nullptr;
}

// A value of the expression: a number (one slot) or a vector (three), and where its text starts.
struct Value {
    bool vector = false;
    int slots[3] = {0, 0, 0};
    std::size_t offset = 0;
};

std::string plural(int n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

class Compiler {
public:
    Compiler(std::string_view text, const ExpressionNames* names)
        : tokens_(tokenize(text)), names_(names), builder_(names != nullptr) {}

    CompiledExpression compile() {
        const Value value = expression();
        if (peek().kind != TokenKind::End) fail(peek().offset, "expected an operator, found " + describe(peek()));
        if (value.vector)
            fail(0, "the expression is a vector; a field is a number (take its length(...) or a component .x)");
        return {builder_.finish(value.slots[0]), field_terms_};
    }

private:
    [[noreturn]] static void fail(std::size_t offset, std::string problem) {
        throw ExpressionError{offset, std::move(problem)};
    }
    static std::string describe(const Token& token) {
        if (token.kind == TokenKind::Name || token.kind == TokenKind::Number)
            return std::string(token_description(token.kind)) + " \"" + std::string(token.text) + "\"";
        return token_description(token.kind);
    }
    const Token& peek() const { return tokens_[at_]; }
    const Token& next() { return tokens_[at_ < tokens_.size() - 1 ? at_++ : at_]; }
    bool accept(TokenKind kind) {
        if (peek().kind != kind) return false;
        next();
        return true;
    }
    void expect(TokenKind kind) {
        if (!accept(kind))
            fail(peek().offset, std::string("expected ") + token_description(kind) + ", found " + describe(peek()));
    }

    // Counts the parser's recursion, which the nesting of the text drives.
    struct Deeper {
        Compiler& compiler;
        Deeper(Compiler& c) : compiler(c) {
            if (++compiler.depth_ > kMaxExpressionNesting)
                fail(c.peek().offset, "the expression nests deeper than " + std::to_string(kMaxExpressionNesting) +
                                          " levels");
        }
        ~Deeper() { --compiler.depth_; }
    };

    Value scalar(int slot, std::size_t offset) const {
        Value v;
        v.slots[0] = slot;
        v.offset = offset;
        return v;
    }
    Value vector(int x, int y, int z, std::size_t offset) const {
        Value v{true, {x, y, z}, offset};
        return v;
    }

    // f applied to each component, numbers standing for themselves in every component.
    Value elementwise(const std::vector<Value>& arguments, std::size_t offset,
                      const std::function<int(const int* slots)>& f) {
        bool any_vector = false;
        for (const Value& a : arguments) any_vector = any_vector || a.vector;
        Value result;
        result.vector = any_vector;
        result.offset = offset;
        for (int k = 0; k < (any_vector ? 3 : 1); ++k) {
            int slots[3] = {0, 0, 0};
            for (std::size_t i = 0; i < arguments.size(); ++i)
                slots[i] = arguments[i].slots[arguments[i].vector ? k : 0];
            result.slots[k] = f(slots);
        }
        return result;
    }
    Value binary(Op op, const Value& a, const Value& b, std::size_t offset) {
        return elementwise({a, b}, offset, [&](const int* s) { return builder_.binary(op, s[0], s[1], offset); });
    }

    const Value& require_scalar(const Value& v, const std::string& what) const {
        if (v.vector) fail(v.offset, what + " must be a number, not a vector");
        return v;
    }
    const Value& require_vector(const Value& v, const std::string& what) const {
        if (!v.vector) fail(v.offset, what + " must be a vector such as p or vec(x, y, z)");
        return v;
    }
    double require_constant(const Value& v, const std::string& what) const {
        require_scalar(v, what);
        const std::optional<double> c = builder_.constant_value(v.slots[0]);
        if (!c) fail(v.offset, what + " must be a constant (numbers and parameters)");
        return *c;
    }
    double constant_between(const Value& v, const std::string& what, double low, double high, bool integer) const {
        const double c = require_constant(v, what);
        if (!(c >= low && c <= high) || (integer && c != std::floor(c)))
            fail(v.offset, what + " must be " + (integer ? "a whole number" : "a number") + " in [" +
                               std::to_string(low) + ", " + std::to_string(high) + "], not " + std::to_string(c));
        return c;
    }

    Value expression() {
        Value value = product();
        for (;;) {
            const std::size_t offset = peek().offset;
            if (accept(TokenKind::Plus)) value = binary(Op::Add, value, product(), offset);
            else if (accept(TokenKind::Minus)) value = binary(Op::Sub, value, product(), offset);
            else return value;
        }
    }

    Value product() {
        Value value = unary();
        for (;;) {
            const std::size_t offset = peek().offset;
            if (accept(TokenKind::Star)) value = binary(Op::Mul, value, unary(), offset);
            else if (accept(TokenKind::Slash)) value = binary(Op::Div, value, unary(), offset);
            else return value;
        }
    }

    // Unary minus binds looser than ^: -x^2 is −(x²), and 2^-1 is allowed.
    Value unary() {
        const std::size_t offset = peek().offset;
        if (accept(TokenKind::Minus)) {
            const Deeper deeper(*this);
            const Value operand = unary();
            return elementwise({operand}, offset, [&](const int* s) { return builder_.unary(Op::Neg, s[0], offset); });
        }
        if (accept(TokenKind::Plus)) {
            const Deeper deeper(*this);
            return unary();
        }
        return power();
    }

    Value power() {
        const Value base = postfix();
        const std::size_t offset = peek().offset;
        if (!accept(TokenKind::Caret)) return base;
        const Deeper deeper(*this);
        const Value exponent = unary();  // right-associative: a^b^c = a^(b^c)
        return raise(base, exponent, offset);
    }

    // Whole constant exponents become multiplications; others exp(b log a), under log's rule.
    Value raise(const Value& base, const Value& exponent, std::size_t offset) {
        const std::optional<double> n = exponent.vector ? std::nullopt : builder_.constant_value(exponent.slots[0]);
        constexpr double kLargestWholeExponent = 1 << 20;
        if (n && *n == std::floor(*n) && std::abs(*n) <= kLargestWholeExponent) {
            const int whole = static_cast<int>(std::abs(*n));
            return elementwise({base}, offset, [&](const int* s) {
                int power = whole == 0 ? builder_.constant(1)
                            : whole == 1 ? s[0]
                            : whole == 2 ? builder_.unary(Op::Square, s[0], offset)
                                         : builder_.emit({Op::PowInt, s[0], 0, 0, whole}, offset);
                return *n < 0 ? builder_.binary(Op::Div, builder_.constant(1), power, offset) : power;
            });
        }
        return elementwise({base, exponent}, offset, [&](const int* s) {
            const int log = builder_.unary(Op::Log, s[0], offset);
            return builder_.unary(Op::Exp, builder_.binary(Op::Mul, s[1], log, offset), offset);
        });
    }

    Value postfix() {
        Value value = primary();
        while (peek().kind == TokenKind::Dot) {
            next();
            const Token& name = next();
            const int component = name.text == "x" ? 0 : name.text == "y" ? 1 : name.text == "z" ? 2 : -1;
            if (name.kind != TokenKind::Name || component < 0)
                fail(name.offset, "expected a component x, y or z after '.', found " + describe(name));
            if (!value.vector) fail(name.offset, "." + std::string(name.text) + " of a number (only vectors have components)");
            value = scalar(value.slots[component], value.offset);
        }
        return value;
    }

    // Each parenthesis, call, sign and exponent is one level of nesting.
    Value primary() {
        const Deeper deeper(*this);
        const Token& token = next();
        switch (token.kind) {
            case TokenKind::Number: return scalar(builder_.constant(token.number), token.offset);
            case TokenKind::Open: {
                Value value = expression();
                expect(TokenKind::Close);
                value.offset = token.offset;
                return value;
            }
            case TokenKind::Name:
                if (accept(TokenKind::Open)) return call(token);
                return name(token);
            default: fail(token.offset, "expected a number, a name or '(', found " + describe(token));
        }
    }

    Value name(const Token& token) {
        const std::string name(token.text);
        const std::size_t offset = token.offset;
        if (name == "p") return vector(builder_.emit({Op::X}, offset), builder_.emit({Op::Y}, offset),
                                       builder_.emit({Op::Z}, offset), offset);
        if (name == "x") return scalar(builder_.emit({Op::X}, offset), offset);
        if (name == "y") return scalar(builder_.emit({Op::Y}, offset), offset);
        if (name == "z") return scalar(builder_.emit({Op::Z}, offset), offset);
        if (name == "pi") return scalar(builder_.constant(std::numbers::pi), offset);
        if (name == "e") return scalar(builder_.constant(std::numbers::e), offset);
        if (names_ == nullptr) return scalar(builder_.constant(1), offset);  // a parameter, presumably
        if (const auto found = names_->parameters.find(name); found != names_->parameters.end()) {
            if (!std::isfinite(found->second))
                fail(offset, "the parameter \"" + name + "\" is " + std::to_string(found->second) + ", not a finite number");
            return scalar(builder_.constant(found->second), offset);
        }
        if (names_->fields.count(name) != 0 || find_function(name) != nullptr)
            fail(offset, "\"" + name + "\" is a function: call it, as in " + name + "(p)");
        std::vector<std::string> known(std::begin(kNames), std::end(kNames));
        for (const auto& [parameter, value] : names_->parameters) known.push_back(parameter);
        fail(offset, "unknown name \"" + name + "\"" + did_you_mean(name, known));
    }

    Value call(const Token& token) {
        std::vector<Value> arguments;
        if (!accept(TokenKind::Close)) {
            do arguments.push_back(expression());
            while (accept(TokenKind::Comma));
            expect(TokenKind::Close);
        }
        const std::string name(token.text);
        if (const FunctionInfo* f = find_function(name)) {
            const int count = static_cast<int>(arguments.size());
            if (count < f->min_arguments || (f->max_arguments >= 0 && count > f->max_arguments)) {
                const std::string expected =
                    f->max_arguments < 0          ? "at least " + plural(f->min_arguments, "argument")
                    : f->min_arguments == f->max_arguments ? plural(f->min_arguments, "argument")
                                                   : std::to_string(f->min_arguments) + " to " +
                                                         plural(f->max_arguments, "argument");
                fail(token.offset, name + " takes " + expected + ", found " + std::to_string(count));
            }
            return builtin(*f, arguments, token.offset);
        }
        return field_term(name, arguments, token.offset);
    }

    Value field_term(const std::string& name, const std::vector<Value>& arguments, std::size_t offset) {
        if (names_ != nullptr && names_->fields.count(name) == 0) {
            std::vector<std::string> known;
            for (const FunctionInfo& f : kFunctions) known.push_back(f.name);
            for (const auto& [field, value] : names_->fields) known.push_back(field);
            fail(offset, "unknown function \"" + name + "\"" + did_you_mean(name, known));
        }
        Value point;
        if (arguments.size() == 1) point = require_vector(arguments[0], "the point of a field term");
        else if (arguments.size() == 3)
            point = vector(require_scalar(arguments[0], "a coordinate").slots[0],
                           require_scalar(arguments[1], "a coordinate").slots[0],
                           require_scalar(arguments[2], "a coordinate").slots[0], offset);
        else fail(offset, "the field term " + name + " takes a point (1 argument) or x, y, z (3 arguments), found " +
                              std::to_string(arguments.size()));
        auto [found, added] = field_index_.try_emplace(name, 0);
        if (added) {
            field_terms_.push_back(name);
            found->second = builder_.add_field(names_ != nullptr ? names_->fields.at(name) : nullptr);
        }
        if (names_ == nullptr) return scalar(builder_.constant(0), offset);  // parsing only: no field to call
        return scalar(builder_.emit({Op::Field, point.slots[0], point.slots[1], point.slots[2], found->second}, offset),
                      offset);
    }

    // smin(a, b, r) = min(a, b) − h²/(4r) with h = max(r − |a − b|, 0), and smax likewise: the polynomial smooth
    // minimum, which differs from min only where |a − b| < r, by at most r/4.
    int smooth(Op pick, int a, int b, double radius, std::size_t offset) {
        const int picked = builder_.binary(pick, a, b, offset);
        if (radius == 0) return picked;
        const int gap = builder_.unary(Op::Abs, builder_.binary(Op::Sub, a, b, offset), offset);
        const int h = builder_.binary(Op::Max, builder_.binary(Op::Sub, builder_.constant(radius), gap, offset),
                                      builder_.constant(0), offset);
        const int bend = builder_.binary(Op::Mul, builder_.unary(Op::Square, h, offset),
                                         builder_.constant(1 / (4 * radius)), offset);
        return builder_.binary(pick == Op::Min ? Op::Sub : Op::Add, picked, bend, offset);
    }

    Value builtin(const FunctionInfo& f, const std::vector<Value>& args, std::size_t offset) {
        const auto unary_op = [&](Op op) {
            return elementwise(args, offset, [&](const int* s) { return builder_.unary(op, s[0], offset); });
        };
        const auto smooth_radius = [&] {
            return constant_between(args[2], std::string("the radius of ") + f.name, 0, HUGE_VAL, false);
        };
        switch (f.builtin) {
            case Builtin::Abs: return unary_op(Op::Abs);
            case Builtin::Sqrt: return unary_op(Op::Sqrt);
            case Builtin::Exp: return unary_op(Op::Exp);
            case Builtin::Log: return unary_op(Op::Log);
            case Builtin::Sin: return unary_op(Op::Sin);
            case Builtin::Cos: return unary_op(Op::Cos);
            case Builtin::Tan: return unary_op(Op::Tan);
            case Builtin::Atan: return unary_op(Op::Atan);
            case Builtin::Atan2: return binary(Op::Atan2, args[0], args[1], offset);
            case Builtin::Min:
            case Builtin::Max: {
                Value value = args[0];
                for (std::size_t i = 1; i < args.size(); ++i)
                    value = binary(f.builtin == Builtin::Min ? Op::Min : Op::Max, value, args[i], offset);
                return value;
            }
            case Builtin::Clamp: return binary(Op::Min, binary(Op::Max, args[0], args[1], offset), args[2], offset);
            case Builtin::Mix:
                return binary(Op::Add, args[0],
                              binary(Op::Mul, binary(Op::Sub, args[1], args[0], offset), args[2], offset), offset);
            case Builtin::Smin:
            case Builtin::Smax:
            case Builtin::Sdiff: {
                const double radius = smooth_radius();
                return elementwise({args[0], args[1]}, offset, [&](const int* s) {
                    if (f.builtin == Builtin::Smin) return smooth(Op::Min, s[0], s[1], radius, offset);
                    if (f.builtin == Builtin::Smax) return smooth(Op::Max, s[0], s[1], radius, offset);
                    return smooth(Op::Max, s[0], builder_.unary(Op::Neg, s[1], offset), radius, offset);
                });
            }
            case Builtin::Length: {
                const Value& v = require_vector(args[0], "the argument of length");
                return scalar(builder_.unary(Op::Sqrt, sum_of_products(v, v, offset), offset), offset);
            }
            case Builtin::Dot:
                return scalar(sum_of_products(require_vector(args[0], "the first argument of dot"),
                                              require_vector(args[1], "the second argument of dot"), offset),
                              offset);
            case Builtin::Vec:
                return vector(require_scalar(args[0], "x of vec").slots[0], require_scalar(args[1], "y of vec").slots[0],
                              require_scalar(args[2], "z of vec").slots[0], offset);
            case Builtin::Noise:
            case Builtin::Simplex:
            case Builtin::Fbm:
            case Builtin::Turbulence:
            case Builtin::Cellular: return noise(f, args, offset);
        }
        return args[0];
    }

    int sum_of_products(const Value& a, const Value& b, std::size_t offset) {
        int sum = -1;
        for (int k = 0; k < 3; ++k) {
            const int product = a.slots[k] == b.slots[k] ? builder_.unary(Op::Square, a.slots[k], offset)
                                                         : builder_.binary(Op::Mul, a.slots[k], b.slots[k], offset);
            sum = sum < 0 ? product : builder_.binary(Op::Add, sum, product, offset);
        }
        return sum;
    }

    Value noise(const FunctionInfo& f, const std::vector<Value>& args, std::size_t offset) {
        const Value& point = require_vector(args[0], std::string("the point of ") + f.name);
        const auto seed_at = [&](std::size_t i) {
            return args.size() > i ? static_cast<std::uint32_t>(
                                         constant_between(args[i], std::string("the seed of ") + f.name, 0, 4294967295.0, true))
                                   : 0u;
        };
        FractalSettings fractal;
        float jitter = 0.5f;
        NoiseKind kind = NoiseKind::Gradient;
        switch (f.builtin) {
            case Builtin::Simplex: kind = NoiseKind::Simplex; [[fallthrough]];
            case Builtin::Noise: fractal.seed = seed_at(1); break;
            case Builtin::Fbm:
            case Builtin::Turbulence: {
                kind = f.builtin == Builtin::Fbm ? NoiseKind::Fbm : NoiseKind::Turbulence;
                const std::string of = std::string(" of ") + f.name;
                if (args.size() > 1)
                    fractal.octaves = static_cast<int>(constant_between(args[1], "the octaves" + of, 1, kMaxFractalOctaves, true));
                if (args.size() > 2)
                    fractal.lacunarity = static_cast<float>(constant_between(args[2], "the lacunarity" + of, 1, 16, false));
                if (args.size() > 3) fractal.gain = static_cast<float>(constant_between(args[3], "the gain" + of, 0, 4, false));
                fractal.seed = seed_at(4);
                break;
            }
            default:
                kind = NoiseKind::Cellular;
                if (args.size() > 1) jitter = static_cast<float>(constant_between(args[1], "the jitter of cellular", 0, 0.5, false));
                fractal.seed = seed_at(2);
        }
        // Each different noise keeps its octaves' tables: bounded here, while the tape's length is checked only
        // once it is built.
        if (builder_.noise_count() >= std::size_t(kMaxExpressionTape))
            fail(offset, std::to_string(kMaxExpressionTape) + " different noises or more: more than a tape of " +
                             std::to_string(kMaxExpressionTape) + " instructions can hold");
        const int index = builder_.add_noise(make_noise_term(kind, fractal, jitter));
        return scalar(builder_.emit({Op::Noise, point.slots[0], point.slots[1], point.slots[2], index}, offset), offset);
    }

    std::vector<Token> tokens_;
    std::size_t at_ = 0;
    int depth_ = 0;
    const ExpressionNames* names_;
    TapeBuilder builder_;
    std::map<std::string, int> field_index_;
    std::vector<std::string> field_terms_;
};

}  // namespace

CompiledExpression compile_expression_text(std::string_view text, const ExpressionNames* names) {
    return Compiler(text, names).compile();
}

bool is_builtin_name(const std::string& name) {
    for (const char* n : kNames)
        if (name == n) return true;
    return find_function(name) != nullptr;
}

}  // namespace isotrace
