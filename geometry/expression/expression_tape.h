#pragma once
// The compiled form of an expression: a flat list of scalar instructions, each writing the slot of its own index
// from the slots of earlier ones. Vectors exist only in the compiler (a vector is three slots), so every
// evaluator works on scalars alone.
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/expression/expression_noise.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

enum class Op : std::uint8_t {
    Constant,  // `constant`
    X, Y, Z,   // the point's coordinates
    Add, Sub, Mul, Div, Neg, Square,
    PowInt,    // slot a to the power `index` (≥ 3)
    Sqrt, Exp, Log, Sin, Cos, Tan, Atan, Atan2, Abs, Min, Max,
    Noise,     // noise `index` of slots a, b, c
    Field,     // field term `index` at the point (a, b, c)
    SinCos,    // sin of slot a, and the next instruction is Cos of slot a: both from one evaluation
};

struct Instruction {
    Op op = Op::Constant;
    std::int32_t a = 0, b = 0, c = 0;  // operand slots
    std::int32_t index = 0;            // exponent, noise or field number
    double constant = 0;
};

struct ExpressionTape {
    std::vector<Instruction> code;  // the last instruction's slot is the value
    std::size_t constants = 0;      // the first instructions, all constants (written without dispatch)
    std::vector<NoiseTerm> noises;
    std::vector<std::shared_ptr<const ImplicitField>> fields;
};

}  // namespace isotrace
