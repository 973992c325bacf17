#include "geometry/implicit/blob_group.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "geometry/implicit/metacube_ray_slices.h"
#include "geometry/polynomial/monotone_root_finder.h"

namespace isotrace {
namespace {

// One element's view of the ray during a query.
struct ActiveElement {
    const Metacube* element;
    MetacubeRaySlices slices;
    const RegionPiece* current = nullptr;  // the element's piece on the ray piece being examined
};

// The element's piece containing t (pieces are contiguous and sorted), or nullptr outside its support.
const RegionPiece* piece_at(const MetacubeRaySlices& slices, double t) {
    if (t < slices.t_in() || t > slices.t_out()) return nullptr;
    for (const RegionPiece& piece : slices.pieces())
        if (t <= piece.t_end) return &piece;
    return &slices.pieces().back();
}

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

// ∑ coefficients[k]·q(u)^k as a polynomial in u.
Polynomial compose_with_quadratic(const FieldPiece& piece, const Polynomial& q) {
    Polynomial result{piece.coefficients[std::size_t(piece.degree)]};
    for (int k = piece.degree - 1; k >= 0; --k) result = result * q + Polynomial{piece.coefficients[std::size_t(k)]};
    return result;
}

// Can the segment o + t·d, t in [a, b], reach the element's support? Tested against the sphere around it
// (centre, R + |half-size|): a few multiplications, a cheap rejection before exact slicing.
bool segment_may_meet(const Metacube& element, const Vec3d& origin, const Vec3d& direction, double a, double b) {
    const Vec3d to_centre = element.skeleton().centre - origin;
    const double t = std::clamp(dot(to_centre, direction) / dot(direction, direction), a, b);
    const double reach = element.radius() + length(element.skeleton().half_size);
    const Vec3d gap = to_centre - direction * t;
    return dot(gap, gap) <= reach * reach * (1 + 1e-9);
}

// Embree asks each element overlapping a ray in turn, and each query slices the same neighbours along the same
// line. Slices do not depend on t_near/t_far, so one thread-local table per ray keeps them: the table is keyed
// by (group, origin, direction) and forgotten by bumping a generation number when the ray changes.
class SliceCache {
public:
    std::optional<MetacubeRaySlices> get(const BlobGroup& group, std::uint32_t element, const Vec3d& origin,
                                         const Vec3d& direction) {
        if (group.identity() != group_ || !(origin == origin_) || !(direction == direction_)) {
            group_ = group.identity();
            origin_ = origin;
            direction_ = direction;
            ++generation_;
        }
        std::size_t slot = (element * 2654435761u) & (kSlots - 1);
        for (int probe = 0; probe < 8; ++probe, slot = (slot + 1) & (kSlots - 1)) {
            Entry& entry = table_[slot];
            if (entry.generation == generation_ && entry.element == element) return entry.slices;
            if (entry.generation != generation_) {
                entry.generation = generation_;
                entry.element = element;
                entry.slices = MetacubeRaySlices::slice(group.elements()[element], origin, direction);
                return entry.slices;
            }
        }
        return MetacubeRaySlices::slice(group.elements()[element], origin, direction);  // table crowded
    }

private:
    static constexpr std::size_t kSlots = 256;
    struct Entry {
        std::uint64_t generation = 0;
        std::uint32_t element = 0;
        std::optional<MetacubeRaySlices> slices;
    };
    std::uint64_t group_ = 0;
    Vec3d origin_, direction_;
    std::uint64_t generation_ = 1;
    std::array<Entry, kSlots> table_{};
};

thread_local SliceCache t_slice_cache;
std::atomic<std::uint64_t> g_next_identity{1};
thread_local std::vector<ActiveElement> t_active;
thread_local std::vector<double> t_breaks;

}  // namespace

BlobGroup::BlobGroup(std::vector<Metacube> elements, std::unique_ptr<const FieldFunction> kernel, double threshold)
    : elements_(std::move(elements)), kernel_(std::move(kernel)), threshold_(threshold), identity_(g_next_identity++) {
    validate_threshold(threshold_);
    build_neighbours();
}

void BlobGroup::build_neighbours() {
    // Uniform grid with cells at least as large as any support box: two supports can overlap only if the cells
    // of their lower corners are adjacent, so each element looks at 27 cells instead of the whole group.
    const std::size_t n = elements_.size();
    std::vector<WorldBounds> bounds(n);
    Vec3d lowest(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                 std::numeric_limits<double>::infinity());
    double cell = 0;
    for (std::size_t i = 0; i < n; ++i) {
        bounds[i] = elements_[i].support_bounds();
        lowest = min(lowest, bounds[i].lower);
        cell = std::max(cell, max_component(bounds[i].upper - bounds[i].lower));
    }
    neighbours_.assign(n, {});
    if (n < 2) return;
    cell = std::max(cell, 1e-300);
    const auto cell_of = [&](const Vec3d& p) {
        std::array<std::int64_t, 3> c{};
        for (int k = 0; k < 3; ++k) c[std::size_t(k)] = std::int64_t(std::floor((p[k] - lowest[k]) / cell));
        return c;
    };
    const auto key_of = [](std::int64_t x, std::int64_t y, std::int64_t z) {
        return (std::uint64_t(x & 0x1FFFFF) << 42) | (std::uint64_t(y & 0x1FFFFF) << 21) | std::uint64_t(z & 0x1FFFFF);
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = cell_of(bounds[i].lower);
        keyed[i] = {key_of(c[0], c[1], c[2]), std::uint32_t(i)};
    }
    std::sort(keyed.begin(), keyed.end());
    // Supports overlap only if both their boxes and their bounding spheres (centre, R + |half-size|) do; for
    // metaballs the sphere test is exact and drops the box corners, about half of the box-only candidates.
    const auto reach = [&](std::size_t i) {
        return elements_[i].radius() + length(elements_[i].skeleton().half_size);
    };
    const auto overlap = [&](std::size_t i, std::size_t j) {
        for (int k = 0; k < 3; ++k)
            if (bounds[i].lower[k] > bounds[j].upper[k] || bounds[j].lower[k] > bounds[i].upper[k]) return false;
        const Vec3d between = elements_[i].skeleton().centre - elements_[j].skeleton().centre;
        const double limit = reach(i) + reach(j);
        return dot(between, between) <= limit * limit * (1 + 1e-9);
    };
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = cell_of(bounds[i].lower);
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    if (c[0] + dx < 0 || c[1] + dy < 0 || c[2] + dz < 0) continue;
                    const std::uint64_t key = key_of(c[0] + dx, c[1] + dy, c[2] + dz);
                    auto it = std::lower_bound(keyed.begin(), keyed.end(), std::make_pair(key, std::uint32_t(0)));
                    for (; it != keyed.end() && it->first == key; ++it)
                        if (it->second != i && overlap(i, it->second)) neighbours_[i].push_back(it->second);
                }
        std::sort(neighbours_[i].begin(), neighbours_[i].end());
        neighbours_[i].shrink_to_fit();
    }
}

void BlobGroup::bake(const Transform& similarity, double scale) {
    for (Metacube& element : elements_) {
        OrientedBox box = element.skeleton();
        box.centre = similarity.point(box.centre);
        for (Vec3d& axis : box.axes) axis = normalize(similarity.vector(axis));
        box.half_size = box.half_size * scale;
        element = Metacube(box, element.radius() * scale, element.weight());
    }
    identity_ = g_next_identity++;
    build_neighbours();
}

std::size_t BlobGroup::memory_bytes() const {
    std::size_t bytes = elements_.capacity() * sizeof(Metacube) + neighbours_.capacity() * sizeof(neighbours_[0]);
    for (const auto& list : neighbours_) bytes += list.capacity() * sizeof(std::uint32_t);
    return bytes;
}

double BlobGroup::field(std::size_t index, const Vec3d& point) const {
    double sum = elements_[index].field(*kernel_, point);
    for (std::uint32_t j : neighbours_[index]) sum += elements_[j].field(*kernel_, point);
    return sum;
}

Vec3d BlobGroup::gradient(std::size_t index, const Vec3d& point) const {
    Vec3d sum = elements_[index].field_gradient(*kernel_, point);
    for (std::uint32_t j : neighbours_[index]) sum += elements_[j].field_gradient(*kernel_, point);
    return sum;
}

Vec3d BlobGroup::normal(std::size_t index, const Vec3d& point) const {
    const Vec3d g = gradient(index, point);
    const double len = length(g);
    if (len > 0 && std::isfinite(len)) return -g / len;
    // Only hard cubes (step fields) meet here: take the face of the nearest hard-cube boundary.
    double best = std::numeric_limits<double>::infinity();
    Vec3d result(0, 0, 1);
    const auto consider = [&](const Metacube& element) {
        if (!element.is_hard_cube()) return;
        const OrientedBox& box = element.skeleton();
        const Vec3d p = box.to_local(point);
        for (int axis = 0; axis < 3; ++axis) {
            const double gap = std::abs(std::abs(p[axis]) - box.half_size[axis]);
            if (gap < best) {
                best = gap;
                Vec3d local(0, 0, 0);
                local[axis] = p[axis] >= 0 ? 1 : -1;
                result = box.to_world_vector(local);
            }
        }
    };
    consider(elements_[index]);
    for (std::uint32_t j : neighbours_[index]) consider(elements_[j]);
    return result;
}

std::optional<double> BlobGroup::first_crossing(std::size_t index, const Vec3d& origin, const Vec3d& direction,
                                                double t_min, double t_max, BlobQueryWork& work) const {
    const auto own = t_slice_cache.get(*this, std::uint32_t(index), origin, direction);
    if (!own) return std::nullopt;
    const double a = std::max(own->t_in(), t_min), b = std::min(own->t_out(), t_max);
    if (!(a < b)) return std::nullopt;

    // Gather every element active somewhere in [a, b] and every breakpoint inside it.
    std::vector<ActiveElement>& active = t_active;
    std::vector<double>& breaks = t_breaks;
    active.clear();
    breaks.clear();
    const auto include = [&](const Metacube& element, const MetacubeRaySlices& slices) {
        if (slices.t_out() <= a || slices.t_in() >= b) return;
        active.push_back({&element, slices, nullptr});
        // Kernel piece boundaries (Nishimura's r = R/3) are breakpoints too.
        const FieldPieces kernel_pieces =
            element.is_hard_cube() || kernel_->unit_pieces().size() < 2 ? FieldPieces{} : kernel_->pieces(element.radius());
        for (const RegionPiece& piece : slices.pieces()) {
            for (double t : {piece.t_begin, piece.t_end})
                if (t > a && t < b) breaks.push_back(t);
            for (int k = 1; k < kernel_pieces.count; ++k)
                add_level_crossings(slices.distance_squared(piece, piece.t_begin), kernel_pieces.pieces[std::size_t(k)].r2_begin,
                                    std::max(a, piece.t_begin), std::min(b, piece.t_end), breaks);
        }
    };
    include(elements_[index], *own);
    for (std::uint32_t j : neighbours_[index]) {
        if (!segment_may_meet(elements_[j], origin, direction, a, b)) continue;
        if (const auto slices = t_slice_cache.get(*this, j, origin, direction)) include(elements_[j], *slices);
    }
    breaks.push_back(a);
    breaks.push_back(b);
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

    // F − T on one piece [s0, s1], as a polynomial in u = t − s0 when every active kernel piece is polynomial.
    const auto field_at = [&](double t) {
        double sum = -threshold_;
        for (const ActiveElement& e : active) {
            const RegionPiece* piece = piece_at(e.slices, t);
            if (!piece) continue;
            if (e.element->is_hard_cube()) {
                if (piece->region == std::array<int, 3>{0, 0, 0}) sum += e.element->weight();
                continue;
            }
            sum += e.element->weight() * kernel_->value(e.slices.distance_squared(*piece, t)(t), e.element->radius());
        }
        return sum;
    };

    // The field just before the interval, so that a hard cube's step at its very entry counts as a crossing.
    double previous_end_value = a > t_min ? field_at(a - 1e-12 * (1 + std::abs(a))) : std::numeric_limits<double>::quiet_NaN();
    for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
        const double s0 = breaks[p], s1 = breaks[p + 1];
        if (!(s1 > s0)) continue;
        ++work.pieces;
        const double middle = 0.5 * (s0 + s1);
        // Every kernel is non-increasing in r², so each element's field on the piece lies between its values at
        // the piece's largest and smallest r². When the summed bounds exclude T the piece has no crossing; only a
        // step at s0 (a hard cube's boundary) can still be one.
        double low = -threshold_, high = -threshold_;
        for (ActiveElement& e : active) {
            e.current = piece_at(e.slices, middle);
            const RegionPiece* piece = e.current;
            if (!piece) continue;
            const double w = e.element->weight();
            if (e.element->is_hard_cube()) {
                if (piece->region == std::array<int, 3>{0, 0, 0}) low += w, high += w;
                continue;
            }
            const Range r2 = quadratic_range(e.slices.distance_squared(*piece, s0), s0, s1);
            const double f_high = w * kernel_->value(r2.low, e.element->radius());
            const double f_low = w * kernel_->value(r2.high, e.element->radius());
            low += std::min(f_low, f_high);
            high += std::max(f_low, f_high);
        }
        const double slack = 1e-12 * (std::abs(low) + std::abs(high) + threshold_);
        if (high < -slack || low > slack) {
            if (std::isfinite(previous_end_value) && (previous_end_value < 0) != (low < 0) && s0 > t_min) {
                ++work.roots;
                return s0;
            }
            previous_end_value = low;  // same sign as the whole piece
            continue;
        }
        Polynomial sum{-threshold_};
        bool polynomial = true;
        double lipschitz = 0;  // bound on |dF/dt| over the piece, for the non-polynomial search
        for (const ActiveElement& e : active) {
            const RegionPiece* piece = e.current;
            if (!piece) continue;
            if (e.element->is_hard_cube()) {
                if (piece->region == std::array<int, 3>{0, 0, 0}) sum += Polynomial{e.element->weight()};
                continue;
            }
            const QuadraticAbout q = e.slices.distance_squared(*piece, s0);
            const double r2_middle = q(middle);
            const FieldPieces kernel_pieces = kernel_->pieces(e.element->radius());
            const FieldPiece* kernel_piece = nullptr;
            for (const FieldPiece& kp : kernel_pieces.span())
                if (r2_middle >= kp.r2_begin && r2_middle <= kp.r2_end) kernel_piece = &kp;
            if (!kernel_piece) continue;  // beyond the support on this piece
            if (kernel_piece->is_polynomial) {
                sum += e.element->weight() * compose_with_quadratic(*kernel_piece, Polynomial{q.c0, q.c1, q.c2});
            } else {
                polynomial = false;
            }
            // |d/dt w f(q(t))| ≤ |w| · max|f'| · max|q'|; f is convex non-increasing in r², so max|f'| is at min q.
            const double slope = std::max(std::abs(q.c1), std::abs(q.c1 + 2 * q.c2 * (s1 - s0)));
            lipschitz += std::abs(e.element->weight()) *
                         std::abs(kernel_->derivative(quadratic_range(q, s0, s1).low, e.element->radius())) * slope;
        }

        // A step (hard cube boundary) across the breakpoint is a crossing at the breakpoint itself.
        const double start_value = polynomial ? sum.evaluate(0) : field_at(s0 + 0.5 * (s1 - s0) * 1e-12);
        if (std::isfinite(previous_end_value) && (previous_end_value < 0) != (start_value < 0) && s0 > t_min) {
            ++work.roots;
            return s0;
        }

        std::optional<double> root;
        if (polynomial) {
            ++work.polynomial_solves;
            if (const auto found = first_root(sum, 0, s1 - s0)) {
                const double t = s0 + found->t;
                if (!found->tangent && t > t_min && t < t_max) root = t;
            }
            previous_end_value = sum.evaluate(s1 - s0);
        } else {
            ++work.lipschitz_searches;
            // Subdivide until a sign change brackets a root, or the Lipschitz bound proves there is none.
            struct Span {
                double lo, hi, f_lo, f_hi;
            };
            Span stack[64];
            int top = 0;
            stack[top++] = {s0, s1, field_at(s0), field_at(s1)};
            while (top > 0 && !root) {
                const Span span = stack[--top];
                if ((span.f_lo < 0) != (span.f_hi < 0)) {
                    double lo = span.lo, hi = span.hi, f_lo = span.f_lo;
                    for (int i = 0; i < 200 && hi - lo > 1e-13 * (1 + std::abs(hi)); ++i) {
                        const double mid = 0.5 * (lo + hi);
                        const double f_mid = field_at(mid);
                        if ((f_mid < 0) == (f_lo < 0)) {
                            lo = mid;
                            f_lo = f_mid;
                        } else {
                            hi = mid;
                        }
                    }
                    if (hi > t_min && hi < t_max) root = hi;
                    continue;
                }
                if (std::abs(span.f_lo) + std::abs(span.f_hi) > lipschitz * (span.hi - span.lo)) continue;
                if (top + 2 > 64 || span.hi - span.lo < 1e-13 * (1 + std::abs(span.hi))) continue;
                const double mid = 0.5 * (span.lo + span.hi);
                const double f_mid = field_at(mid);
                stack[top++] = {mid, span.hi, f_mid, span.f_hi};  // the nearer half is searched first
                stack[top++] = {span.lo, mid, span.f_lo, f_mid};
            }
            previous_end_value = field_at(s1);
        }
        if (root) {
            ++work.roots;
            return root;
        }
    }
    return std::nullopt;
}

}  // namespace isotrace
