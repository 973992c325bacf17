#pragma once
// The march over one stretch of a ray (a cell's part of it), front to back, piece by piece: between consecutive
// events (an element's entry or exit, a boundary of a kernel piece or of a metacube's slices) every counting element's
// term is one closed form. Each piece is settled by bounds where it can be, else tested and solved (march_piece.h),
// and every crossing goes to the query in increasing t. F > 0 is inside; F = 0 exactly counts as outside.
//
// What differs between the two ways of holding the elements is the parameter `Elements`: MetaballMarch's lanes
// (metaball_march.h) or FieldMarch's list of joined elements (field_march.h). It provides
//   threshold();
//   start(t): makes the elements that count at t current and returns F just after t;
//   counting_weights(t): Σ |wᵢ| over those elements (F + T cannot exceed it: the scale of F's rounding);
//   settles_stretch(t0, at_start, previous_sign, march): shortcuts over the whole stretch (true: the march ends);
//   next_event(t0, t_end): where the piece from t0 ends, at most t_end, its counting elements made current;
//   bound_piece(t0, t1, previous_sign, march): PieceBound, from cheap bounds of F on the piece;
//   test_piece(t0, t1): PieceTest, from the piece's polynomial (or hull) when the bounds leave it open;
//   kAllPolynomial, or else search_piece(t0, t1, previous_sign, march): the crossings of an open piece that is no
//     polynomial (true: stop);
//   advance(t1): moves the elements on past the events at t1;
//   at_end(t_end, previous_sign, march): a crossing just at the stretch's end, if any;
//   witness(): an element counting on the current piece; gradient_at(point): ∇(F + T) there, for the query.
// `march` is the PieceMarch: crossing(t, sign before) reports a crossing (true: stop), and kPlaceNeeded is false
// where the query needs no crossing's place (occlusion), so that a crossing may be reported anywhere on its piece.
#include <algorithm>
#include <utility>

#include "geometry/implicit/march_piece.h"

namespace isotrace {

// What the bounds of F on a piece show.
struct PieceBound {
    bool stop = false;     // a crossing was reported and the query wants no more
    bool settled = false;  // F keeps one sign on the piece
    int start_sign = -1;   // that sign, when settled
};

// The polynomial test of a piece the bounds leave open.
struct PieceTest {
    bool open = true;                         // a crossing may lie on the piece
    int start_sign = -1;                      // F's sign at the piece's start, when it is not open
    const Polynomial* polynomial = nullptr;   // F on the piece in u ∈ [0, 1]; nullptr: no polynomial (search it)
    BernsteinSigns signs;                     // of the polynomial's control polygon
};

template <class Elements, class Query>
class PieceMarch {
public:
    PieceMarch(Elements& elements, const MarchStretch& stretch, BlobQueryWork& work, Query& query)
        : elements_(elements), stretch_(stretch), work_(work), query_(query) {}

    void run() {
        double t0 = stretch_.t_begin;
        const double at_start = elements_.start(t0);
        int previous_sign = march_piece::sign_of(at_start);
        // Inside at a stretch that starts after t_min: the query may know a crossing lies before it.
        if (previous_sign > 0 && t0 > stretch_.t_min &&
            march_piece::inside_beyond_rounding(at_start, elements_.threshold(), elements_.counting_weights(t0)) &&
            query_.crossed_before())
            return;
        if (elements_.settles_stretch(t0, at_start, previous_sign, *this)) return;
        while (t0 < stretch_.t_end) {
            const double t1 = elements_.next_event(t0, stretch_.t_end);
            if (t1 > t0 && march_piece(t0, t1, previous_sign)) return;
            if (t1 >= stretch_.t_end) {
                elements_.at_end(stretch_.t_end, previous_sign, *this);
                return;
            }
            elements_.advance(t1);
            t0 = t1;
        }
    }

    // Reports a crossing at t from sign `before` to the other, if t lies in (t_min, t_max); true when the query
    // stops the march.
    bool crossing(double t, int before) {
        if (!(t > stretch_.t_min && t < stretch_.t_max)) return false;
        ++work_.roots;
        return query_.found(FieldCrossing{t, before < 0, elements_.witness()}, std::as_const(elements_));
    }

    static constexpr bool kPlaceNeeded = Query::kPlaceNeeded;
    const MarchStretch& stretch() const { return stretch_; }
    BlobQueryWork& work() { return work_; }

private:
    // The piece [t0, t1]; previous_sign is F's sign just before it, and at its end on return. True: stop.
    bool march_piece(double t0, double t1, int& previous_sign) {
        ++work_.pieces;
        const PieceBound bound = elements_.bound_piece(t0, t1, previous_sign, *this);
        if (bound.stop) return true;
        const PieceTest test =
            bound.settled ? PieceTest{false, bound.start_sign, nullptr, {}} : elements_.test_piece(t0, t1);
        if (!test.open) {
            ++work_.skipped_pieces;
            // Only a step at t0 (a hard cube's face, or a root the previous piece ended on within rounding) can be a
            // crossing here.
            if (test.start_sign != previous_sign && crossing(t0, previous_sign)) return true;
            previous_sign = test.start_sign;
            return false;
        }
        if constexpr (!Elements::kAllPolynomial)
            if (!test.polynomial) return elements_.search_piece(t0, t1, previous_sign, *this);
        return march_piece::polynomial_piece_crossings(*test.polynomial, test.signs, t0, t1 - t0, previous_sign, work_,
                                                       [this](double t, int before) { return crossing(t, before); });
    }

    Elements& elements_;
    const MarchStretch& stretch_;
    BlobQueryWork& work_;
    Query& query_;
};

}  // namespace isotrace
