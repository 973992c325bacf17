#include "geometry/expression/gradient_noise_bounds.h"

#include <array>
#include <cmath>

#include "renderer/math/vec3.h"
#include "renderer/textures/patterns/gradient_noise.h"
#include "renderer/textures/patterns/lattice.h"

namespace isotrace {
namespace {

constexpr double kUnscaledExtreme = kGradientNoiseUnscaledExtreme;  // gradient_noise divides its sum by it
constexpr double kCoordinateLimit = 0x1p22;

// The fade 6t⁵ − 15t⁴ + 10t³ is increasing on [0, 1]: its range is that of its ends.
double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
Interval fade_range(Interval t) { return {fade(t.lo), fade(t.hi)}; }
// Its derivative 30 (t (1 − t))², where t (1 − t) rises to ¼ at t = ½ and falls after.
Interval fade_slope_range(Interval t) {
    const auto hump = [](double s) { return s * (1 - s); };
    Interval h = Interval::spanning(hump(t.lo), hump(t.hi));
    if (t.lo <= 0.5 && 0.5 <= t.hi) h.hi = 0.25;
    return square(h) * 30.0;
}

// (1 − t) a + t b for t in [0, 1] and independent a, b: linear in t at either end of a and b, so the extremes are
// at t's ends (exact, unlike the interval form of a + t (b − a), which counts a twice).
Interval lerp_range(Interval t, Interval a, Interval b) {
    return {std::min((1 - t.lo) * a.lo + t.lo * b.lo, (1 - t.hi) * a.lo + t.hi * b.lo),
            std::max((1 - t.lo) * a.hi + t.lo * b.hi, (1 - t.hi) * a.hi + t.hi * b.hi)};
}

// Corner values indexed by a + 2b + 4c for the corner (a, b, c) of the cell.
using Corners = std::array<Interval, 8>;

Interval trilinear(const Interval fades[3], const Corners& v) {
    const auto along_x = [&](int bc) { return lerp_range(fades[0], v[2 * bc], v[2 * bc + 1]); };
    return lerp_range(fades[2], lerp_range(fades[1], along_x(0), along_x(1)), lerp_range(fades[1], along_x(2), along_x(3)));
}

struct CornerGradient {
    double g[3];
};

// One lattice cell's part of a box: the corners' gradients, the coordinates minus the cell's corner (in [0, 1])
// and their fades.
struct CellPart {
    CornerGradient gradients[8];
    Interval offsets[3];
    Interval fades[3];
};

CellPart cell_part(std::uint32_t root, const std::int32_t (&cell)[3], const IntervalBox& box) {
    CellPart part;
    for (int k = 0; k < 3; ++k) {
        part.offsets[k] = {std::max(box[k].lo - cell[k], 0.0), std::min(box[k].hi - cell[k], 1.0)};
        part.fades[k] = fade_range(part.offsets[k]);
    }
    const CellGradients gradients = cell_gradients(root, cell);  // the texture's own
    for (int corner = 0; corner < 8; ++corner)
        for (int k = 0; k < 3; ++k) part.gradients[corner].g[k] = gradients.g[corner][k];
    return part;
}

// Each corner's g · (offsets − corner): linear, each coordinate once, so exact.
Interval corner_dot(const double g[3], int corner, const Interval offsets[3]) {
    Interval sum = Interval::point(0);
    for (int k = 0; k < 3; ++k) sum = sum + (offsets[k] + -static_cast<double>((corner >> k) & 1)) * g[k];
    return sum;
}

// The value's bound over a cell's part: the corners' dots blended by the fades.
Interval cell_value(const CellPart& part) {
    Corners dots;
    for (int corner = 0; corner < 8; ++corner) dots[corner] = corner_dot(part.gradients[corner].g, corner, part.offsets);
    return trilinear(part.fades, dots);
}

// The bounds over one cell's part of the box.
NoiseBoxBounds cell_bounds(const CellPart& part) {
    const Interval* offsets = part.offsets;
    const Interval* fades = part.fades;
    const auto& gradients = part.gradients;
    NoiseBoxBounds bounds;
    bounds.value = cell_value(part);
    for (int k = 0; k < 3; ++k) {
        // ∂n/∂x_k = fade′(x_k) × (the blend of the differences across axis k) + the blend of the g_k.
        Corners across, partial;
        for (int corner = 0; corner < 8; ++corner) {
            const int far = corner | (1 << k), near = corner & ~(1 << k);
            double difference[3];
            for (int m = 0; m < 3; ++m) difference[m] = gradients[far].g[m] - gradients[near].g[m];
            // dot(far) − dot(near) with each coordinate once: (g_far − g_near) · (offsets − near) − g_far,k.
            across[corner] = corner_dot(difference, near, offsets) + -gradients[far].g[k];
            partial[corner] = Interval::point(gradients[corner].g[k]);
        }
        Interval flat[3] = {fades[0], fades[1], fades[2]};
        flat[k] = {0, 0};  // the differences do not depend on corner's k bit: blend the k = 0 ones
        bounds.gradient[k] = fade_slope_range(offsets[k]) * trilinear(flat, across) + trilinear(fades, partial);
    }
    return bounds;
}

bool within_limits(const IntervalBox& box) {
    for (int k = 0; k < 3; ++k)
        if (!(box[k].lo >= -kCoordinateLimit && box[k].hi <= kCoordinateLimit)) return false;
    return true;
}

// The hull of the cells' bounds, unscaled; nothing beyond the limits.
std::optional<NoiseBoxBounds> bounds_over_cells(const IntervalBox& box, std::uint32_t seed) {
    if (!within_limits(box)) return std::nullopt;
    std::int32_t first[3], last[3];
    int cells = 1;
    for (int k = 0; k < 3; ++k) {
        first[k] = static_cast<std::int32_t>(std::floor(box[k].lo));
        last[k] = static_cast<std::int32_t>(std::floor(box[k].hi));
        cells *= last[k] - first[k] + 1;
        if (cells > kMaxBoundedNoiseCells) return std::nullopt;
    }
    const std::uint32_t root = lattice_seed(seed);
    std::optional<NoiseBoxBounds> hull_of_cells;
    for (std::int32_t i = first[0]; i <= last[0]; ++i)
        for (std::int32_t j = first[1]; j <= last[1]; ++j)
            for (std::int32_t l = first[2]; l <= last[2]; ++l) {
                NoiseBoxBounds b = cell_bounds(cell_part(root, {i, j, l}, box));
                if (!hull_of_cells) {
                    hull_of_cells = b;
                    continue;
                }
                hull_of_cells->value = hull(hull_of_cells->value, b.value);
                for (int k = 0; k < 3; ++k) hull_of_cells->gradient[k] = hull(hull_of_cells->gradient[k], b.gradient[k]);
            }
    return hull_of_cells;
}

// bounds_over_cells' value at a point (which meets one cell), without the gradient's bounds.
std::optional<Interval> value_at_point(const Vec3d& q, std::uint32_t seed) {
    const IntervalBox box = IntervalBox::point(q);
    if (!within_limits(box)) return std::nullopt;
    const std::int32_t cell[3] = {static_cast<std::int32_t>(std::floor(q.x)), static_cast<std::int32_t>(std::floor(q.y)),
                                  static_cast<std::int32_t>(std::floor(q.z))};
    return cell_value(cell_part(lattice_seed(seed), cell, box));
}

}  // namespace

std::optional<NoiseBoxBounds> gradient_noise_bounds(const IntervalBox& box, std::uint32_t seed) {
    std::optional<NoiseBoxBounds> bounds = bounds_over_cells(box, seed);
    if (!bounds) return std::nullopt;
    // The mean-value form n(c) + ∇n(box) · (box − c), tighter than the cell formula's own interval on small boxes
    // (its excess shrinks with the square of the width, not the width); a point's value is exact already.
    const bool is_point = box.x.width() == 0 && box.y.width() == 0 && box.z.width() == 0;
    if (!is_point) {
        Vec3d centre;
        for (int k = 0; k < 3; ++k) centre[k] = 0.5 * (box[k].lo + box[k].hi);
        Interval mean_value = *value_at_point(centre, seed);
        for (int k = 0; k < 3; ++k) mean_value = mean_value + bounds->gradient[k] * (box[k] + -centre[k]);
        bounds->value = {std::max(bounds->value.lo, mean_value.lo), std::min(bounds->value.hi, mean_value.hi)};
    }
    const double scale = 1 / kUnscaledExtreme;
    bounds->value = bounds->value * scale;
    for (int k = 0; k < 3; ++k) bounds->gradient[k] = bounds->gradient[k] * scale;
    return bounds;
}

std::optional<Interval> gradient_noise_value_at(const Vec3d& q, std::uint32_t seed) {
    const std::optional<Interval> value = value_at_point(q, seed);
    if (!value) return std::nullopt;
    return *value * (1 / kUnscaledExtreme);
}

}  // namespace isotrace
