#pragma once
// Builds an expression tape instruction by instruction: an instruction whose operands are all constants is
// computed at once (constant folding), one that repeats an earlier instruction reuses its slot (common
// subexpressions), and finish() drops the instructions the value does not depend on.
#include <cstddef>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "geometry/expression/expression_tape.h"

namespace isotrace {

class TapeBuilder {
public:
    // With `check_constants`, a folded constant outside its operation's domain (0/0, sqrt(−1), log(0)) or not
    // finite is an ExpressionError at `offset`; without, the domain rules apply (for parsing without the names).
    explicit TapeBuilder(bool check_constants) : check_constants_(check_constants) {}

    int emit(const Instruction& instruction, std::size_t offset);
    int constant(double value);
    int unary(Op op, int a, std::size_t offset) { return emit({op, a}, offset); }
    int binary(Op op, int a, int b, std::size_t offset) { return emit({op, a, b}, offset); }
    // The slot's value when it holds a constant: a copy, since emitting moves the tape.
    std::optional<double> constant_value(int slot) const;

    int add_noise(const NoiseTerm& term);
    std::size_t noise_count() const { return tape_.noises.size(); }
    int add_field(std::shared_ptr<const ImplicitField> field);

    // The tape of the instructions that `output` depends on, `output` last.
    ExpressionTape finish(int output) const;

private:
    using Key = std::tuple<Op, int, int, int, int, double>;

    ExpressionTape tape_;
    std::vector<bool> is_constant_;
    std::map<Key, int> slots_;
    bool check_constants_;
};

// How many operand slots an operation reads (0 to 3).
int operand_count(Op op);

}  // namespace isotrace
