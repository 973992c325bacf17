#include "geometry/implicit/field_along_ray.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/polynomial/monotone_root_finder.h"

namespace isotrace {
namespace {

constexpr std::array<int, 3> kInsideBox{0, 0, 0};

int sign_of(double value) { return value > 0 ? 1 : -1; }

// t values in (a, b) where the quadratic q (about q.t_ref) equals level, appended to `out`.
void add_level_crossings(const QuadraticAbout& q, double level, double a, double b, std::vector<double>& out) {
    const double c = q.c0 - level;
    double roots[2];
    int count = 0;
    if (q.c2 == 0) {
        if (q.c1 != 0) roots[count++] = q.t_ref - c / q.c1;
    } else {
        const double discriminant = q.c1 * q.c1 - 4 * q.c2 * c;
        if (discriminant < 0) return;
        const double k = -0.5 * (q.c1 + std::copysign(std::sqrt(discriminant), q.c1));  // cancellation-free pair
        if (k != 0) roots[count++] = q.t_ref + c / k;
        roots[count++] = q.t_ref + k / q.c2;
    }
    for (int i = 0; i < count; ++i)
        if (roots[i] > a && roots[i] < b) out.push_back(roots[i]);
}

// Smallest and largest value of the quadratic q on [s0, s1] (q is a squared distance: never below 0).
struct Range {
    double low, high;
};
Range quadratic_range(const QuadraticAbout& q, double s0, double s1) {
    const double at_s0 = q(s0), at_s1 = q(s1);
    const double vertex = q.c2 > 0 ? std::clamp(q.t_ref - q.c1 / (2 * q.c2), s0, s1) : s0;
    return {std::max(0.0, std::min({at_s0, at_s1, q(vertex)})), std::max(at_s0, at_s1)};
}

// w·∑ coefficients[k]·q^k as a polynomial in u = t − q.t_ref, by Horner's rule on coefficient arrays (this runs
// for every active element of every solved piece, so it avoids general polynomial products).
Polynomial composed_with_quadratic(const FieldPiece& piece, double weight, const QuadraticAbout& q) {
    std::array<double, kMaxPolynomialDegree + 1> acc{};
    acc[0] = piece.coefficients[std::size_t(piece.degree)];
    std::size_t degree = 0;
    for (int k = piece.degree - 1; k >= 0; --k) {
        std::array<double, kMaxPolynomialDegree + 1> next{};
        for (std::size_t i = 0; i <= degree; ++i) {
            next[i] += acc[i] * q.c0;
            next[i + 1] += acc[i] * q.c1;
            next[i + 2] += acc[i] * q.c2;
        }
        next[0] += piece.coefficients[std::size_t(k)];
        acc = next;
        degree += 2;
    }
    for (std::size_t i = 0; i <= degree; ++i) acc[i] *= weight;
    return Polynomial(std::span<const double>(acc.data(), degree + 1));
}

}  // namespace

BlobQueryWork& BlobQueryWork::operator+=(const BlobQueryWork& other) {
    pieces += other.pieces;
    skipped_pieces += other.skipped_pieces;
    polynomial_solves += other.polynomial_solves;
    lipschitz_searches += other.lipschitz_searches;
    root_iterations += other.root_iterations;
    roots += other.roots;
    return *this;
}

void FieldAlongRay::reset(const FieldFunction& kernel, double threshold, double a, double b) {
    kernel_ = &kernel;
    threshold_ = threshold;
    a_ = a;
    b_ = b;
    active_.clear();
    breaks_.clear();
}

void FieldAlongRay::add(std::uint32_t index, const Metacube& element, const MetacubeRaySlices& slices) {
    if (slices.t_out() <= a_ || slices.t_in() >= b_) return;
    Active& e = active_.emplace_back();
    e.index = index;
    e.element = &element;
    e.slices = &slices;
    // The kernel's pieces are needed for breakpoints only by multi-piece kernels (Nishimura's r = R/3); others
    // get them when a piece is solved (most pieces are skipped by their bounds).
    const bool multi_piece = !element.is_hard_cube() && kernel_->unit_pieces().size() > 1;
    if (multi_piece) e.kernel_pieces = kernel_->pieces(element.radius());
    for (const RegionPiece& piece : slices.pieces()) {
        for (double t : {piece.t_begin, piece.t_end})
            if (t > a_ && t < b_) breaks_.push_back(t);
        for (int k = 1; multi_piece && k < e.kernel_pieces.count; ++k)
            add_level_crossings(slices.distance_squared(piece, piece.t_begin),
                                e.kernel_pieces.pieces[std::size_t(k)].r2_begin, std::max(a_, piece.t_begin),
                                std::min(b_, piece.t_end), breaks_);
    }
}

double FieldAlongRay::value(double t) const {
    double sum = -threshold_;
    for (const Active& e : active_) {
        const MetacubeRaySlices& slices = *e.slices;
        if (t < slices.t_in() || t > slices.t_out()) continue;
        const RegionPiece* piece = &slices.pieces().back();
        for (const RegionPiece& p : slices.pieces())
            if (t <= p.t_end) {
                piece = &p;
                break;
            }
        if (e.element->is_hard_cube()) {
            if (piece->region == kInsideBox) sum += e.element->weight();
            continue;
        }
        sum += e.element->weight() * kernel_->value(slices.distance_squared(*piece, t)(t), e.element->radius());
    }
    return sum;
}

FieldAlongRay::Stop FieldAlongRay::crossings(double t_min, double t_max, int sign_before_a, std::size_t max_count,
                                             std::vector<FieldCrossing>& out, BlobQueryWork& work) {
    breaks_.push_back(a_);
    breaks_.push_back(b_);
    std::sort(breaks_.begin(), breaks_.end());
    breaks_.erase(std::unique(breaks_.begin(), breaks_.end()), breaks_.end());
    for (Active& e : active_) e.cursor = 0;

    std::size_t found = 0;
    bool complete = true;
    // Reports a crossing at t where F goes from sign `before` to the other; true when the search must stop.
    const auto report = [&](double t, int before, std::uint32_t element) {
        if (!(t > t_min && t < t_max)) {
            complete = false;
            return false;
        }
        ++work.roots;
        out.push_back({t, before < 0, element});
        return ++found >= max_count;
    };

    int previous_sign = sign_before_a;
    if (previous_sign == 0 && a_ > t_min) previous_sign = sign_of(value(a_ - 1e-12 * (1 + std::abs(a_))));
    for (std::size_t p = 0; p + 1 < breaks_.size(); ++p) {
        const double s0 = breaks_[p], s1 = breaks_[p + 1];
        if (!(s1 > s0)) continue;
        ++work.pieces;
        const double middle = 0.5 * (s0 + s1);
        // Every kernel is non-increasing in r², so each element's field on the piece lies between its values at
        // the piece's largest and smallest r². When the summed bounds exclude T the piece has no crossing; only a
        // step at s0 (a hard cube's boundary) can still be one.
        double low = -threshold_, high = -threshold_;
        std::uint32_t witness = active_.empty() ? 0 : active_.front().index;  // an element live on the piece
        for (Active& e : active_) {
            const MetacubeRaySlices& slices = *e.slices;
            e.current = nullptr;
            if (middle < slices.t_in() || middle > slices.t_out()) continue;
            const auto pieces = slices.pieces();
            while (e.cursor + 1 < pieces.size() && pieces[e.cursor].t_end < middle) ++e.cursor;
            e.current = &pieces[e.cursor];
            witness = e.index;
            const double w = e.element->weight();
            if (e.element->is_hard_cube()) {
                if (e.current->region == kInsideBox) low += w, high += w;
                continue;
            }
            const Range r2 = quadratic_range(slices.distance_squared(*e.current, s0), s0, s1);
            const double f_high = w * kernel_->value(r2.low, e.element->radius());
            const double f_low = w * kernel_->value(r2.high, e.element->radius());
            low += std::min(f_low, f_high);
            high += std::max(f_low, f_high);
        }
        const double slack = 1e-12 * (std::abs(low) + std::abs(high) + threshold_);
        if (high < -slack || low > slack) {
            ++work.skipped_pieces;
            const int sign = sign_of(low);
            if (previous_sign != 0 && previous_sign != sign &&
                report(s0, previous_sign, witness))
                return {s0, previous_sign, complete};
            previous_sign = sign;
            continue;
        }

        Polynomial sum{-threshold_};
        bool polynomial = true;
        double lipschitz = 0;  // bound on |dF/dt| over the piece, for the non-polynomial search
        for (Active& e : active_) {
            if (!e.current) continue;
            if (e.element->is_hard_cube()) {
                if (e.current->region == kInsideBox) sum += Polynomial{e.element->weight()};
                continue;
            }
            if (e.kernel_pieces.count == 0) e.kernel_pieces = kernel_->pieces(e.element->radius());
            const QuadraticAbout q = e.slices->distance_squared(*e.current, s0);
            const double r2_middle = q(middle);
            const FieldPiece* kernel_piece = nullptr;
            for (const FieldPiece& kp : e.kernel_pieces.span())
                if (r2_middle >= kp.r2_begin && r2_middle <= kp.r2_end) kernel_piece = &kp;
            if (!kernel_piece) continue;  // beyond the support on this piece
            if (kernel_piece->is_polynomial) {
                sum += composed_with_quadratic(*kernel_piece, e.element->weight(), q);
            } else {
                polynomial = false;
            }
            // |d/dt w f(q(t))| ≤ |w| · max|f'| · max|q'|; f is convex non-increasing in r², so max|f'| is at min q.
            const double slope = std::max(std::abs(q.c1), std::abs(q.c1 + 2 * q.c2 * (s1 - s0)));
            lipschitz += std::abs(e.element->weight()) *
                         std::abs(kernel_->derivative(quadratic_range(q, s0, s1).low, e.element->radius())) * slope;
        }

        // A step (hard cube boundary) across the breakpoint is a crossing at the breakpoint itself.
        const double start_value = polynomial ? sum.evaluate(0) : value(s0 + 0.5 * (s1 - s0) * 1e-12);
        if (previous_sign != 0 && previous_sign != sign_of(start_value) &&
            report(s0, previous_sign, witness))
            return {s0, previous_sign, complete};
        previous_sign = sign_of(start_value);

        if (polynomial) {
            ++work.polynomial_solves;
            // Roots in order; a tangent root touches without crossing (see monotone_root_finder.h), and a root
            // whose direction repeats the last sign change is the piece-start step found again.
            RootFinderWork root_work;
            const double width = s1 - s0;
            for (double from = 0; from <= width;) {
                const auto root = first_root(sum, from, width, {}, &root_work);
                if (!root) break;
                from = root->t + 1e-12 * width;
                if (root->tangent) continue;
                const int after = sum.evaluate_with_derivative(root->t).derivative > 0 ? 1 : -1;
                if (after == previous_sign) continue;
                const int before = previous_sign;
                previous_sign = after;
                const double t = s0 + root->t;
                if (report(t, before, witness)) {
                    work.root_iterations += root_work.iterations;
                    return {t, before, complete};
                }
            }
            work.root_iterations += root_work.iterations;
            previous_sign = sign_of(sum.evaluate(s1 - s0));
        } else {
            ++work.lipschitz_searches;
            // Subdivide until a sign change brackets a root, or the Lipschitz bound proves there is none; nearer
            // halves first, so crossings come out in increasing t.
            struct Span {
                double lo, hi, f_lo, f_hi;
            };
            Span stack[64];
            int top = 0;
            stack[top++] = {s0, s1, value(s0), value(s1)};
            while (top > 0) {
                const Span span = stack[--top];
                if ((span.f_lo < 0) != (span.f_hi < 0)) {
                    double lo = span.lo, hi = span.hi, f_lo = span.f_lo;
                    for (int i = 0; i < 200 && hi - lo > 1e-13 * (1 + std::abs(hi)); ++i) {
                        ++work.root_iterations;
                        const double mid = 0.5 * (lo + hi);
                        const double f_mid = value(mid);
                        if ((f_mid < 0) == (f_lo < 0)) {
                            lo = mid;
                            f_lo = f_mid;
                        } else {
                            hi = mid;
                        }
                    }
                    const int before = sign_of(span.f_lo);
                    previous_sign = -before;
                    if (report(hi, before, witness)) return {hi, before, complete};
                    continue;
                }
                if (std::abs(span.f_lo) + std::abs(span.f_hi) > lipschitz * (span.hi - span.lo)) continue;
                if (top + 2 > 64 || span.hi - span.lo < 1e-13 * (1 + std::abs(span.hi))) continue;
                ++work.root_iterations;
                const double mid = 0.5 * (span.lo + span.hi);
                const double f_mid = value(mid);
                stack[top++] = {mid, span.hi, f_mid, span.f_hi};
                stack[top++] = {span.lo, mid, span.f_lo, f_mid};
            }
            previous_sign = sign_of(value(s1));
        }
    }
    return {b_, previous_sign, complete};
}

}  // namespace isotrace
