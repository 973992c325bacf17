// The shell grid against a ball of radius 0.5 in the box [−1, 1]³, whose field range over a box is known exactly
// (distance to the nearest and farthest point, minus the radius): every crossing of a random line lies in a run,
// the runs are ordered, disjoint and inside the line's stretch, a run's cells meet end to end and their bounds hold
// the field and its slope along the line, the sign a run is told for either side is the field's there, lines
// through the box's empty corners have none, a visit that returns false stops the walk, a copy keeps what was
// found, and a point's cell tells the field's sign there where it holds no surface. A star-like field, whose gradient is
// unbounded on the coordinate planes, has its cells there split into eighths with bounds of their own.
#include "geometry/superquadric/surface_shell.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "geometry/sphere/sphere_intersection.h"
#include "renderer/math/line_box_clip.h"

namespace isotrace {
namespace {

constexpr double kRadius = 0.5;
const IntervalBox kBox{{-1, 1}, {-1, 1}, {-1, 1}};

Interval ball_range(const IntervalBox& box) {
    double near = 0, far = 0;
    for (int k = 0; k < 3; ++k) {
        const double lo = box[k].lo, hi = box[k].hi;
        const double nearest = lo > 0 ? lo : hi < 0 ? hi : 0, farthest = std::max(std::abs(lo), std::abs(hi));
        near += nearest * nearest, far += farthest * farthest;
    }
    return {std::sqrt(near) - kRadius, std::sqrt(far) - kRadius};
}

// The ball's field |x| − r at a centre and its gradient x/|x| over a box, by interval arithmetic.
ShellCellBounds ball_bounds(const IntervalBox& box, const Vec3d& centre) {
    ShellCellBounds bounds;
    const Interval distance = ball_range(box) + kRadius;
    if (!(distance.lo > 0)) return bounds;  // the gradient is unbounded at the centre
    const Interval inverse{1 / distance.hi, 1 / distance.lo};
    for (int k = 0; k < 3; ++k) bounds.gradient[k] = box[k] * inverse;
    bounds.centre = centre, bounds.value = length(centre) - kRadius, bounds.known = true;
    return bounds;
}

struct RunStretch {
    double lo, hi;
};

using Range = Interval (*)(const IntervalBox&);

// The runs of a line as the walk hands them over, each made of cells whose stretches meet end to end.
std::vector<RunStretch> runs_of(const SurfaceShell& shell, const Vec3d& o, const Vec3d& d, int* ranges = nullptr,
                                Range range = ball_range) {
    std::vector<RunStretch> runs;
    const auto clip = clip_line_to_box(kBox.lower(), kBox.upper(), o, d, 0, 100);
    if (!clip) return runs;
    int calls = 0;
    shell.visit_runs(o, d, clip->t_enter, clip->t_exit, [&](const IntervalBox& b) { ++calls; return range(b); },
                     ball_bounds, [&](const SurfaceShell::Run& run) {
                         EXPECT_GE(run.lo(), clip->t_enter);
                         EXPECT_LE(run.hi(), clip->t_exit);
                         EXPECT_GT(run.size(), 0u);
                         for (std::size_t k = 0; k < run.size(); ++k) {
                             EXPECT_LE(run.start(k), run.end(k));
                             if (k > 0) { EXPECT_EQ(run.start(k), run.end(k - 1)); }
                         }
                         runs.push_back({run.lo(), run.hi()});
                         return true;
                     });
    if (ranges) *ranges = calls;
    return runs;
}

// Lines from around the box toward the ball: the runs come in order and every crossing of the ball lies in one.
// Returns how many crossings there were.
int crossings_in_runs(const SurfaceShell& shell, std::uint32_t seed, int lines, Range range = ball_range) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    int crossings = 0;
    for (int i = 0; i < lines; ++i) {
        const Vec3d o = normalize(Vec3d{unit(random), unit(random), unit(random)}) * 3.0;
        const Vec3d d = Vec3d{unit(random), unit(random), unit(random)} * 0.6 - o;
        const std::vector<RunStretch> runs = runs_of(shell, o, d, nullptr, range);
        for (std::size_t k = 1; k < runs.size(); ++k) EXPECT_GT(runs[k].lo, runs[k - 1].hi);
        const auto roots = intersect_sphere(o, d, {0, 0, 0}, kRadius);
        if (!roots) continue;
        for (const double t : {roots->t0, roots->t1}) {
            ++crossings;
            bool inside = false;
            for (const RunStretch& r : runs) inside = inside || (t >= r.lo && t <= r.hi);
            EXPECT_TRUE(inside) << "ray " << i << " crossing at " << t;
        }
    }
    return crossings;
}

TEST(SurfaceShell, EveryCrossingLiesInARun) {
    const SurfaceShell shell(kBox);
    EXPECT_GT(crossings_in_runs(shell, 3, 2000), 1000);
}

// The runs of a plain cell-by-cell walk that asks every cell's range and own bounds itself: the same runs to the bit,
// also for lines through grid vertices and along grid planes, where the walk's ties between axes decide the order of
// the cells.
std::vector<RunStretch> runs_cell_by_cell(const Vec3d& o, const Vec3d& d) {
    std::vector<RunStretch> runs;
    const auto clip = clip_line_to_box(kBox.lower(), kBox.upper(), o, d, 0, 100);
    if (!clip) return runs;
    const double t0 = clip->t_enter, t1 = clip->t_exit, pad = 1e-9 * (t1 - t0);
    constexpr int n = SurfaceShell::kCellsPerAxis;
    const double size = 2.0 / n;
    // A cell holds the surface where its range and its own bounds (over the cell enlarged as the shell takes it)
    // both hold zero.
    const auto holds_surface = [&](int i, int j, int l) {
        const auto side = [&](int at) { return Interval{-1 + at * size, at + 1 == n ? 1 : -1 + (at + 1) * size}; };
        const auto holds_zero = [](const Interval& g) { return !(g.lo > 0 || g.hi < 0); };
        const IntervalBox cell{side(i), side(j), side(l)};
        if (!holds_zero(ball_range(cell))) return false;
        IntervalBox around = cell;
        for (int k = 0; k < 3; ++k) around[k] = {cell[k].lo - 1e-6 * size, cell[k].hi + 1e-6 * size};
        const ShellCellBounds own = ball_bounds(around, (cell.lower() + cell.upper()) * 0.5);
        return !own.known || holds_zero(own.range(around));
    };
    const Vec3d start = o + d * t0;
    int cell[3];
    for (int k = 0; k < 3; ++k) cell[k] = std::clamp(int(std::floor((start[k] + 1) / size)), 0, n - 1);
    // The walk's formulas: the first plane from its position, the later ones a cell's width in t further.
    double across[3];
    for (int k = 0; k < 3; ++k)
        across[k] = d[k] == 0 ? std::numeric_limits<double>::infinity()
                              : (-1 + (cell[k] + (d[k] > 0 ? 1 : 0)) * size - o[k]) * (1 / d[k]);
    double enter = t0, run_start = 0;
    bool in_run = false;
    const auto add = [&](double a, double b) {
        a = std::max(t0, a - pad), b = std::min(t1, b + pad);
        if (!runs.empty() && a <= runs.back().hi) runs.back().hi = b;
        else runs.push_back({a, b});
    };
    while (true) {
        const int axis = across[0] <= across[1] && across[0] <= across[2] ? 0 : across[1] <= across[2] ? 1 : 2;
        const bool surface = holds_surface(cell[0], cell[1], cell[2]);
        if (surface && !in_run) in_run = true, run_start = enter;
        if (!surface && in_run) in_run = false, add(run_start, enter);
        const double leave = std::min(across[axis], t1);
        cell[axis] += d[axis] > 0 ? 1 : -1;
        across[axis] += size * std::abs(1 / d[axis]);
        if (!(leave < t1) || cell[axis] < 0 || cell[axis] >= n) break;
        enter = std::max(enter, leave);
    }
    if (in_run) add(run_start, t1);
    return runs;
}

TEST(SurfaceShell, RunsAreThoseOfTheCellByCellWalkToTheBit) {
    const SurfaceShell shell(kBox);
    std::mt19937 random(9);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> vertex(0, SurfaceShell::kCellsPerAxis);
    const auto grid = [&] { return -1 + vertex(random) * (2.0 / SurfaceShell::kCellsPerAxis); };
    for (int i = 0; i < 3000; ++i) {
        Vec3d o = normalize(Vec3d{unit(random), unit(random), unit(random)}) * 3.0;
        Vec3d d = Vec3d{unit(random), unit(random), unit(random)} * 0.8 - o;
        if (i % 3 == 1) {  // through two grid vertices
            const Vec3d a{grid(), grid(), grid()}, b{grid(), grid(), grid()};
            if (a == b) continue;
            o = a - (b - a) * 2.0, d = b - a;
        } else if (i % 3 == 2) {  // along a grid plane
            o.z = grid(), d.z = 0;
        }
        const std::vector<RunStretch> expected = runs_cell_by_cell(o, d), actual = runs_of(shell, o, d);
        ASSERT_EQ(actual.size(), expected.size()) << "line " << i;
        for (std::size_t k = 0; k < actual.size(); ++k) {
            EXPECT_EQ(actual[k].lo, expected[k].lo) << "line " << i;
            EXPECT_EQ(actual[k].hi, expected[k].hi) << "line " << i;
        }
    }
}

TEST(SurfaceShell, EachCellsBoundsHoldTheFieldAndItsSlopeAlongTheLine) {
    const SurfaceShell shell(kBox);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1);
    int known = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3d o = normalize(Vec3d{unit(random), unit(random), unit(random)}) * 3.0;
        const Vec3d d = Vec3d{unit(random), unit(random), unit(random)} * 0.6 - o;
        const auto clip = clip_line_to_box(kBox.lower(), kBox.upper(), o, d, 0, 100);
        if (!clip) continue;
        shell.visit_runs(o, d, clip->t_enter, clip->t_exit, ball_range, ball_bounds, [&](const SurfaceShell::Run& run) {
            for (std::size_t c = 0; c < run.size(); ++c) {
                const ShellCellBounds cell = run.bounds(c);
                if (!cell.known) continue;
                ++known;
                const double a = run.start(c), b = run.end(c);
                const Interval range = cell.range(o + d * a, o + d * b), slope = cell.slope(d);
                for (int k = 0; k <= 8; ++k) {
                    const Vec3d p = o + d * (a + (b - a) * (k < 8 ? fraction(random) : 1.0));
                    EXPECT_TRUE(range.contains(length(p) - kRadius)) << "line " << i;
                    EXPECT_TRUE(slope.contains(dot(p, d) / length(p))) << "line " << i;
                }
            }
            return true;
        });
    }
    EXPECT_GT(known, 1000);
}

// Lines from outside the box, from random points inside it and along grid planes: where a run is told the field's
// sign beside it, the field has that sign at the run's padded end (strictly), and runs from outside to inside are
// common (a line through the ball).
TEST(SurfaceShell, ARunsSidesAreTheFieldsSignsBesideIt) {
    const SurfaceShell shell(kBox);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> vertex(0, SurfaceShell::kCellsPerAxis);
    int told = 0, into = 0;
    for (int i = 0; i < 3000; ++i) {
        Vec3d o = i % 3 == 0 ? normalize(Vec3d{unit(random), unit(random), unit(random)}) * 3.0
                             : Vec3d{unit(random), unit(random), unit(random)} * 0.99;
        Vec3d d = Vec3d{unit(random), unit(random), unit(random)} * 0.8 - o * (i % 3 == 0 ? 1.0 : 0.0);
        if (i % 3 == 2) o.z = -1 + vertex(random) * (2.0 / SurfaceShell::kCellsPerAxis), d.z = 0;
        if (length(d) == 0) continue;
        const auto clip = clip_line_to_box(kBox.lower(), kBox.upper(), o, d, 0, 100);
        if (!clip) continue;
        shell.visit_runs(o, d, clip->t_enter, clip->t_exit, ball_range, ball_bounds, [&](const SurfaceShell::Run& run) {
            const auto check = [&](SurfaceShell::Side side, double t) {
                if (side == SurfaceShell::Side::Unknown) return;
                ++told;
                const double g = length(o + d * t) - kRadius;
                EXPECT_EQ(side == SurfaceShell::Side::Inside, g < 0) << "line " << i << " at " << t;
                EXPECT_NE(g, 0.0) << "line " << i;
            };
            check(run.before, run.lo());
            check(run.after, run.hi());
            into += run.before == SurfaceShell::Side::Outside && run.after == SurfaceShell::Side::Inside;
            return true;
        });
    }
    EXPECT_GT(told, 2000);
    EXPECT_GT(into, 300);
}

TEST(SurfaceShell, LinesThroughEmptyCornersHaveNoRuns) {
    const SurfaceShell shell(kBox);
    EXPECT_TRUE(runs_of(shell, {-2, 0.9, 0.9}, {1, 0, 0}).empty());  // along an edge, 1.27 from the centre
    EXPECT_EQ(runs_of(shell, {-2, 0, 0}, {1, 0, 0}).size(), 2u);     // through the centre: in and out
}

TEST(SurfaceShell, AVisitThatReturnsFalseStopsTheWalk) {
    const SurfaceShell shell(kBox);
    int visits = 0;
    const bool finished =
        shell.visit_runs({-2, 0, 0}, {1, 0, 0}, 1, 3, ball_range, ball_bounds, [&](const SurfaceShell::Run&) {
            ++visits;
            return false;
        });
    EXPECT_FALSE(finished);
    EXPECT_EQ(visits, 1);
}

TEST(SurfaceShell, BlocksAreFoundOnceAndKeptByCopies) {
    const SurfaceShell shell(kBox);
    int first = 0, again = 0, copied = 0;
    runs_of(shell, {-2, 0.1, 0}, {1, 0, 0}, &first);
    runs_of(shell, {-2, 0.1, 0}, {1, 0, 0}, &again);
    const SurfaceShell copy = shell;
    runs_of(copy, {-2, 0.1, 0}, {1, 0, 0}, &copied);
    EXPECT_GT(first, 0);
    EXPECT_EQ(again, 0);
    EXPECT_EQ(copied, 0);
}

// A point's cell tells the field's sign where the cell holds no surface: inside near the centre, outside in the
// corners; in a surface cell, or within rounding of a cell's face, it tells nothing. Random points: a sign told is
// the field's.
TEST(SurfaceShell, APointsCellTellsTheSignWhereItHoldsNoSurface) {
    const SurfaceShell shell(kBox);
    const double cell = 2.0 / SurfaceShell::kCellsPerAxis;
    using Side = SurfaceShell::Side;
    EXPECT_EQ(shell.side_at({0.3 * cell, 0.4 * cell, 0.6 * cell}, ball_range, ball_bounds), Side::Inside);
    EXPECT_EQ(shell.side_at({0.9 - 0.5 * cell, 0.9, 0.9 - 0.3 * cell}, ball_range, ball_bounds), Side::Outside);
    EXPECT_EQ(shell.side_at({kRadius + 0.3 * cell, 0.4 * cell, 0.6 * cell}, ball_range, ball_bounds), Side::Unknown);
    EXPECT_EQ(shell.side_at({0, 0.4 * cell, 0.6 * cell}, ball_range, ball_bounds), Side::Unknown);  // on a face
    EXPECT_EQ(shell.side_at({2, 0, 0}, ball_range, ball_bounds), Side::Unknown);                     // beyond the box
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(-1, 1);
    int told = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3d p{unit(random), unit(random), unit(random)};
        const Side side = shell.side_at(p, ball_range, ball_bounds);
        if (side == Side::Unknown) continue;
        ++told;
        EXPECT_EQ(side == Side::Inside, length(p) < kRadius) << p.x << " " << p.y << " " << p.z;
    }
    EXPECT_GT(told, 1800);
}

// A range that clears nothing (as an interval walk through a strong twist may): the cells' own bounds still tell
// which cells hold no surface, and the sign there. Every crossing still lies in a run, and a line that passes far
// from the ball has none.
TEST(SurfaceShell, ACellsOwnBoundsClearItWhereTheRangeCannot) {
    const SurfaceShell shell(kBox);
    const Range clears_nothing = [](const IntervalBox&) { return Interval::unbounded(); };
    const double cell = 2.0 / SurfaceShell::kCellsPerAxis;
    using Side = SurfaceShell::Side;
    EXPECT_EQ(shell.side_at({0.25 + 0.3 * cell, 0.4 * cell, 0.6 * cell}, clears_nothing, ball_bounds), Side::Inside);
    EXPECT_EQ(shell.side_at({0.9 - 0.5 * cell, 0.9, 0.9 - 0.3 * cell}, clears_nothing, ball_bounds), Side::Outside);
    EXPECT_EQ(shell.side_at({kRadius + 0.3 * cell, 0.4 * cell, 0.6 * cell}, clears_nothing, ball_bounds),
              Side::Unknown);
    EXPECT_TRUE(runs_of(shell, {-2, 0.8, 0.1}, {1, 0, 0}, nullptr, clears_nothing).empty());
    EXPECT_GT(crossings_in_runs(shell, 17, 1000, clears_nothing), 500);
}

// (√|x| + √|y| + √|z|)² − r: star-like, with creases on the coordinate planes, where its gradient is unbounded; so
// the shell cells that touch them keep no bounds of their own and are split into eighths. Its range over a box: the
// nearest and the farthest |xᵢ| on each axis.
constexpr double kStar = 0.6;

double star_sum(const Vec3d& p) { return std::sqrt(std::abs(p.x)) + std::sqrt(std::abs(p.y)) + std::sqrt(std::abs(p.z)); }

double star_field(const Vec3d& p) {
    const double s = star_sum(p);
    return s * s - kStar;
}

Interval star_roots(const Interval& side) {
    const double nearest = side.lo > 0 ? side.lo : side.hi < 0 ? -side.hi : 0;
    return {std::sqrt(nearest), std::sqrt(std::max(std::abs(side.lo), std::abs(side.hi)))};
}

Interval star_sum(const IntervalBox& box) { return star_roots(box.x) + star_roots(box.y) + star_roots(box.z); }

Interval star_range(const IntervalBox& box) {
    const Interval sum = star_sum(box);
    return {sum.lo * sum.lo - kStar, sum.hi * sum.hi - kStar};
}

// ∂/∂xᵢ = sign(xᵢ)·S/√|xᵢ| with S = Σ√|xⱼ|: bounded only over boxes that keep off the planes.
ShellCellBounds star_bounds(const IntervalBox& box, const Vec3d& centre) {
    ShellCellBounds bounds;
    const Interval sum = star_sum(box);
    for (int k = 0; k < 3; ++k) {
        if (!(box[k].lo > 0 || box[k].hi < 0)) return bounds;
        const Interval root = star_roots(box[k]), slope{sum.lo / root.hi, sum.hi / root.lo};
        bounds.gradient[k] = box[k].lo > 0 ? slope : Interval{-slope.hi, -slope.lo};
    }
    bounds.centre = centre, bounds.value = star_field(centre), bounds.known = true;
    return bounds;
}

double star_slope(const Vec3d& p, const Vec3d& d) {
    const double s = star_sum(p);
    double slope = 0;
    for (int k = 0; k < 3; ++k) slope += std::copysign(s / std::sqrt(std::abs(p[k])), p[k]) * d[k];
    return slope;
}

// Whether the cell of the grid that holds p (away from its faces) keeps no bounds of its own though it can hold
// the surface: a cell the shell splits.
bool in_cell_without_bounds(const Vec3d& p) {
    constexpr int n = SurfaceShell::kCellsPerAxis;
    const double size = 2.0 / n;
    IntervalBox cell;
    for (int k = 0; k < 3; ++k) {
        const double at = std::floor((p[k] + 1) / size);
        cell[k] = {-1 + at * size, -1 + (at + 1) * size};
    }
    const Interval g = star_range(cell);
    return g.lo <= 0 && g.hi >= 0 && !star_bounds(cell, (cell.lower() + cell.upper()) * 0.5).known;
}

// Lines from around the box: every sign change of the field (sampled finely) lies in a run, the bounds of each
// stretch that has them hold the field and its slope along it, and many such stretches are eighths of cells without
// bounds (their centres a quarter of a cell from the grid's cell centres).
TEST(SurfaceShell, CellsWithoutBoundsAreSplitIntoEighthsWithBoundsOfTheirOwn) {
    const SurfaceShell shell(kBox);
    std::mt19937 random(21);
    std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1);
    const double cell = 2.0 / SurfaceShell::kCellsPerAxis;
    int sign_changes = 0, eighths_known = 0;
    for (int i = 0; i < 600; ++i) {
        const Vec3d o = normalize(Vec3d{unit(random), unit(random), unit(random)}) * 3.0;
        const Vec3d d = Vec3d{unit(random), unit(random), unit(random)} * 0.4 - o;
        const auto clip = clip_line_to_box(kBox.lower(), kBox.upper(), o, d, 0, 100);
        if (!clip) continue;
        std::vector<RunStretch> runs;
        shell.visit_runs(o, d, clip->t_enter, clip->t_exit, star_range, star_bounds, [&](const SurfaceShell::Run& run) {
            for (std::size_t c = 0; c < run.size(); ++c) {
                if (c > 0) { EXPECT_EQ(run.start(c), run.end(c - 1)); }
                const ShellCellBounds bounds = run.bounds(c);
                if (!bounds.known) continue;
                const double quarter = std::abs(std::fmod(bounds.centre.x + 1, cell) / cell - 0.5);
                eighths_known += std::abs(quarter - 0.25) < 1e-9;
                const double a = run.start(c), b = run.end(c);
                const Interval range = bounds.range(o + d * a, o + d * b), slope = bounds.slope(d);
                for (int k = 0; k <= 8; ++k) {
                    const Vec3d p = o + d * (a + (b - a) * (k < 8 ? fraction(random) : 1.0));
                    EXPECT_TRUE(range.contains(star_field(p))) << "line " << i;
                    EXPECT_TRUE(slope.contains(star_slope(p, d))) << "line " << i;
                }
            }
            runs.push_back({run.lo(), run.hi()});
            return true;
        });
        constexpr int kSamples = 4000;
        const double t0 = clip->t_enter, t1 = clip->t_exit;
        double previous = star_field(o + d * t0);
        for (int k = 1; k <= kSamples; ++k) {
            const double t = t0 + (t1 - t0) * k / kSamples, g = star_field(o + d * t);
            if ((g < 0) != (previous < 0)) {
                ++sign_changes;
                const double before = t0 + (t1 - t0) * (k - 1) / kSamples;
                bool covered = false;
                for (const RunStretch& r : runs) covered = covered || (r.lo <= t && r.hi >= before);
                EXPECT_TRUE(covered) << "line " << i << " sign change in [" << before << ", " << t << "]";
            }
            previous = g;
        }
    }
    EXPECT_GT(sign_changes, 500);
    EXPECT_GT(eighths_known, 100);
}

// Where a line leaves or enters a run beside an eighth without surface, the sign the run is told is the field's; and
// a point in a split cell's eighth without surface is told its sign.
TEST(SurfaceShell, AnEighthWithoutSurfaceTellsItsSign) {
    const SurfaceShell shell(kBox);
    std::mt19937 random(23);
    std::uniform_real_distribution<double> unit(-1, 1);
    int told = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3d o{unit(random) * 0.9, unit(random) * 0.9, unit(random) * 0.9}, d{unit(random), unit(random), unit(random)};
        const auto clip = clip_line_to_box(kBox.lower(), kBox.upper(), o, d, 0, 100);
        if (!clip) continue;
        shell.visit_runs(o, d, clip->t_enter, clip->t_exit, star_range, star_bounds, [&](const SurfaceShell::Run& run) {
            for (const auto& [side, t] : {std::pair{run.before, run.lo()}, std::pair{run.after, run.hi()}}) {
                if (side == SurfaceShell::Side::Unknown) continue;
                const double g = star_field(o + d * t);
                EXPECT_EQ(side == SurfaceShell::Side::Inside, g < 0) << "line " << i << " at " << t;
            }
            return true;
        });
    }
    for (int i = 0; i < 20000; ++i) {
        const Vec3d p{unit(random) * 0.7, unit(random) * 0.7, unit(random) * 0.7};
        const SurfaceShell::Side side = shell.side_at(p, star_range, star_bounds);
        if (side == SurfaceShell::Side::Unknown) continue;
        EXPECT_EQ(side == SurfaceShell::Side::Inside, star_field(p) < 0) << p.x << " " << p.y << " " << p.z;
        told += in_cell_without_bounds(p);
    }
    EXPECT_GT(told, 50);
}

}  // namespace
}  // namespace isotrace
