#pragma once
// Runs a tape in any of the number types of expression_arithmetic.h: one interpreter for the value, the gradient,
// the interval and the interval slope. The slots live on the stack (kMaxExpressionTape of them), so an
// evaluation allocates nothing and shares nothing with other threads.
#include "geometry/expression/expression_arithmetic.h"
#include "geometry/expression/expression_field.h"
#include "geometry/expression/expression_tape.h"

namespace isotrace::expression_math {

// Noise and field terms of each number type.
inline double noise(const NoiseTerm& term, double x, double y, double z) { return noise_value(term, {x, y, z}); }
inline Interval noise(const NoiseTerm& term, Interval x, Interval y, Interval z) {
    return noise_value_range(term, {x, y, z});
}
template <class D>
Dual<double, D> noise(const NoiseTerm& term, const Dual<double, D>& x, const Dual<double, D>& y, const Dual<double, D>& z) {
    const Vec3d q{x.v, y.v, z.v};
    const Vec3d g = noise_gradient(term, q);
    return {noise_value(term, q), x.d * g.x + y.d * g.y + z.d * g.z};
}
inline IntervalSlope noise(const NoiseTerm& term, const IntervalSlope& x, const IntervalSlope& y,
                           const IntervalSlope& z) {
    const NoiseBoxRanges ranges = noise_box_ranges(term, {x.v, y.v, z.v});
    return {ranges.value, noise_slope_range(term, ranges, {x.d, y.d, z.d})};
}
// The box's bounds once, each partial's slope from them as an IntervalSlope run along that axis takes it.
inline IntervalGradient noise(const NoiseTerm& term, const IntervalGradient& x, const IntervalGradient& y,
                              const IntervalGradient& z) {
    const NoiseBoxRanges ranges = noise_box_ranges(term, {x.v, y.v, z.v});
    return {ranges.value,
            {noise_slope_range(term, ranges, {x.d.x, y.d.x, z.d.x}), noise_slope_range(term, ranges, {x.d.y, y.d.y, z.d.y}),
             noise_slope_range(term, ranges, {x.d.z, y.d.z, z.d.z})}};
}

inline double field(const ImplicitField& f, double x, double y, double z) { return f.value({x, y, z}); }
inline Interval field(const ImplicitField& f, Interval x, Interval y, Interval z) { return f.value_range({x, y, z}); }
template <class D>
Dual<double, D> field(const ImplicitField& f, const Dual<double, D>& x, const Dual<double, D>& y, const Dual<double, D>& z) {
    const Vec3d q{x.v, y.v, z.v};
    const Vec3d g = f.gradient(q);
    return {f.value(q), x.d * g.x + y.d * g.y + z.d * g.z};
}
// The slope along the point's own direction of motion when that is one direction (the term's argument is p moved
// rigidly, say); otherwise the partial derivatives' bounds times the motion's components.
inline Interval field_slope(const ImplicitField& f, const IntervalBox& box, Interval dx, Interval dy, Interval dz) {
    if (dx.width() == 0 && dy.width() == 0 && dz.width() == 0) return f.slope_range(box, {dx.lo, dy.lo, dz.lo});
    return f.slope_range(box, {1, 0, 0}) * dx + f.slope_range(box, {0, 1, 0}) * dy + f.slope_range(box, {0, 0, 1}) * dz;
}
inline IntervalSlope field(const ImplicitField& f, const IntervalSlope& x, const IntervalSlope& y,
                           const IntervalSlope& z) {
    const IntervalBox box{x.v, y.v, z.v};
    return {f.value_range(box), field_slope(f, box, x.d, y.d, z.d)};
}
inline IntervalGradient field(const ImplicitField& f, const IntervalGradient& x, const IntervalGradient& y,
                              const IntervalGradient& z) {
    const IntervalBox box{x.v, y.v, z.v};
    return {f.value_range(box),
            {field_slope(f, box, x.d.x, y.d.x, z.d.x), field_slope(f, box, x.d.y, y.d.y, z.d.y),
             field_slope(f, box, x.d.z, y.d.z, z.d.z)}};
}

template <class N>
N constant(double c) {
    if constexpr (std::is_same_v<N, double>) return c;
    else if constexpr (std::is_same_v<N, Interval>) return Interval::point(c);
    else return N{decltype(N::v)(constant<decltype(N::v)>(c)), decltype(N::d){}};
}

// One instruction, given the slots before it and the point (x, y, z), settled (settle()). Always inlined into the
// loop of run(): a call per instruction cost a third of a small tape's time. The operations that keep settled
// operands settled (negation, |a|, min, max, sin, cos, atan: values and derivatives scaled by at most 1) skip
// settle(), which ran after every instruction and was 10–20 % of the interpreter's time.
template <class N>
[[gnu::always_inline]] inline N apply(const ExpressionTape& tape, const Instruction& in, const N* slots, const N& x, const N& y, const N& z) {
    const N& a = slots[in.a];
    const N& b = slots[in.b];
    switch (in.op) {
        case Op::Constant: return settle(constant<N>(in.constant));
        case Op::X: return settle(x);
        case Op::Y: return settle(y);
        case Op::Z: return settle(z);
        case Op::Add: return settle(a + b);
        case Op::Sub: return settle(a - b);
        case Op::Mul: return settle(a * b);
        case Op::Div: return settle(divide(a, b));
        case Op::Neg: return -a;
        case Op::Square: return settle(square(a));
        case Op::PowInt: return settle(pow_int(a, in.index));
        case Op::Sqrt: return settle(sqrt(a));
        case Op::Exp: return settle(exp(a));
        case Op::Log: return settle(log(a));
        case Op::Sin:
        case Op::SinCos: return sin(a);  // run() writes the pair's cosine too
        case Op::Cos: return cos(a);
        case Op::Tan: return settle(tan(a));
        case Op::Atan: return atan(a);
        case Op::Atan2: return settle(atan2(a, b));
        case Op::Abs: return abs(a);
        case Op::Min: return min(a, b);
        case Op::Max: return max(a, b);
        case Op::Noise: return settle(noise(tape.noises[in.index], a, b, slots[in.c]));
        case Op::Field: return settle(field(*tape.fields[in.index], a, b, slots[in.c]));
    }
    return a;
}

// Every slot of the tape at the point (x, y, z), into slots[0 .. tape.code.size()).
template <class N>
[[gnu::always_inline]] inline void run_into(const ExpressionTape& tape, const N& x, const N& y, const N& z, N* slots) {
    const std::size_t count = tape.code.size();
    for (std::size_t i = 0; i < tape.constants; ++i) slots[i] = constant<N>(tape.code[i].constant);
    for (std::size_t i = tape.constants; i < count; ++i) {
        const Instruction& in = tape.code[i];
        if (in.op == Op::SinCos) {
            const auto both = sin_cos(slots[in.a]);
            slots[i] = both.sin;
            slots[++i] = both.cos;
            continue;
        }
        slots[i] = apply(tape, in, slots, x, y, z);
    }
}

// The tape's value at the point (x, y, z).
template <class N>
N run(const ExpressionTape& tape, const N& x, const N& y, const N& z) {
    union Slot {
        N value;
        Slot() {}  // left uninitialised: each instruction writes its slot before any later one reads it
    };
    Slot slots[kMaxExpressionTape];
    static_assert(sizeof(Slot) == sizeof(N));
    run_into(tape, x, y, z, &slots[0].value);
    return slots[tape.code.size() - 1].value;
}

}  // namespace isotrace::expression_math
