#pragma once
// A tape specialised to a box (libfive's tape pruning: Keeter, "Massively Parallel Rendering of Complex Closed-Form
// Implicit Surfaces"): where interval arithmetic over the box settles which operand a min or max selects, or the
// sign of |a|'s operand, the instruction becomes that operand (or its negation) and whatever only the other
// operand needed drops out. The smooth blends of the language are min(a, b) − h²/(4r) with h = max(r − |a − b|,
// 0): where |a − b| ≥ r over the box, h is the constant 0 and the blend folds to the min (or max) alone.
// Point values inside the box are those of the whole tape (the operand selected is the one the whole tape
// selects there, up to the sign of a zero and ties between equal operands); interval bounds over boxes within it
// are as tight or tighter.
#include <cstdint>
#include <vector>

#include "geometry/expression/expression_tape.h"
#include "renderer/math/interval.h"

namespace isotrace {

// What interval arithmetic settles over `box`, one entry per instruction of `tape`: 0 for nothing, 1 for the first
// operand (min, max, |a| with a ≥ 0), 2 for the second (min, max), 3 for −a (|a| with a ≤ 0). Equal choices give
// equal pruned tapes.
std::vector<std::uint8_t> settled_choices(const ExpressionTape& tape, const IntervalBox& box);

// `tape` with `choices` (from settled_choices) made: constants folded and dead instructions dropped.
ExpressionTape pruned_tape(const ExpressionTape& tape, const std::vector<std::uint8_t>& choices);

}  // namespace isotrace
