#pragma once
// The cells of a uniform grid over a deformed superquadric's box that can hold its surface: those where the interval
// range of g contains zero. Elsewhere g keeps one sign throughout a cell, and (g being continuous) throughout any
// chain of such cells, so a ray needs searching only along its runs of shell cells: rays that pass the object
// through its box's empty corners cost a walk through the grid, and the interval bounds over a run are tighter
// than over the whole box, since they wrap a shorter piece of the ray's inverse-deformed curve.
//
// The grid is found as rays need it, a block of 4³ cells at a time (the block first, its cells only when the block
// can hold the surface): a scene of many deformed superquadrics, each seen by a few pixels, does not pay for
// grids no ray walks. Threads that meet an unknown block at once both find it, with the same answer; the block's
// word is published by a release store.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>

#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

class SurfaceShell {
public:
    static constexpr int kCellsPerAxis = 32;

    SurfaceShell() = default;
    explicit SurfaceShell(const IntervalBox& box) : box_(box) {
        for (int k = 0; k < 3; ++k) cell_size_[k] = box[k].width() / kCellsPerAxis;
    }
    SurfaceShell(const SurfaceShell& other) { *this = other; }
    SurfaceShell& operator=(const SurfaceShell& other) {
        box_ = other.box_;
        std::copy(std::begin(other.cell_size_), std::end(other.cell_size_), std::begin(cell_size_));
        for (int b = 0; b < kBlocks; ++b) {
            const bool known = other.known_[b].load(std::memory_order_acquire);
            cells_[b].store(known ? other.cells_[b].load(std::memory_order_relaxed) : 0, std::memory_order_relaxed);
            known_[b].store(known, std::memory_order_release);
        }
        return *this;
    }

    // Calls visit(a, b) for the runs [a, b] of shell cells along origin + t·direction within [t0, t1] (the part of
    // the line inside the box), in increasing t, until it returns false (then returns false). `range(cell)`
    // contains g over a box inside the grid's. Each run is widened by 10⁻⁹ of [t0, t1] so that the rounding of the
    // cell boundaries cannot cut a crossing off; runs that then touch are joined.
    template <class Range, class Visit>
    bool visit_runs(const Vec3d& origin, const Vec3d& direction, double t0, double t1, const Range& range,
                    Visit&& visit) const {
        const double pad = 1e-9 * (t1 - t0);
        bool pending = false;
        double pending_lo = 0, pending_hi = 0;
        const auto add_run = [&](double a, double b) {
            a = std::max(t0, a - pad), b = std::min(t1, b + pad);
            if (pending && a <= pending_hi) {
                pending_hi = b;
                return true;
            }
            if (pending && !visit(pending_lo, pending_hi)) return false;
            pending = true, pending_lo = a, pending_hi = b;
            return true;
        };
        // Per axis in arrays: Vec3's component access by index is a chain of branches in this loop.
        const Vec3d start = origin + direction * t0;
        const double from[3] = {origin.x, origin.y, origin.z}, along[3] = {direction.x, direction.y, direction.z},
                     lower[3] = {box_.x.lo, box_.y.lo, box_.z.lo}, first[3] = {start.x, start.y, start.z};
        int cell_of[3];
        for (int k = 0; k < 3; ++k)
            cell_of[k] = std::clamp(int(std::floor((first[k] - lower[k]) / cell_size_[k])), 0, kCellsPerAxis - 1);
        // Where the line leaves the current cell across each axis' next plane.
        const auto next_plane = [&](int k) {
            if (along[k] == 0) return std::numeric_limits<double>::infinity();
            const int plane = cell_of[k] + (along[k] > 0 ? 1 : 0);
            return (lower[k] + plane * cell_size_[k] - from[k]) / along[k];
        };
        double enter = t0, run_start = 0;
        bool in_run = false;
        // Only the axis whose plane was crossed moves on: the others keep their next plane.
        double across[3] = {next_plane(0), next_plane(1), next_plane(2)};
        // The surface bits of the block the walk is in, looked up again only when it enters another.
        int block_index = -1;
        std::uint64_t block = 0;
        for (int step = 0; step <= 3 * kCellsPerAxis; ++step) {  // a line crosses at most 3·n cells
            const CellIndex cell{cell_of[0], cell_of[1], cell_of[2]};
            if (const int index = block_of(cell); index != block_index) block_index = index, block = block_cells(cell, range);
            const bool surface = (block >> bit(cell)) & 1;
            if (surface && !in_run) in_run = true, run_start = enter;
            if (!surface && in_run) {
                in_run = false;
                if (!add_run(run_start, enter)) return false;
            }
            int axis = across[0] <= across[1] && across[0] <= across[2] ? 0 : across[1] <= across[2] ? 1 : 2;
            if (block == 0) {
                // No cell of this block holds the surface: step straight to where the line leaves the block, the
                // cells and planes on the way taken as the cell by cell walk takes them (the same plane formula,
                // ties to the lower axis), so that the runs after it are the same to the bit.
                double block_exit = std::numeric_limits<double>::infinity();
                int last_in_block[3];
                for (int k = 0; k < 3; ++k) {
                    last_in_block[k] = cell_of[k] / kBlock * kBlock + (along[k] > 0 ? kBlock - 1 : 0);
                    if (along[k] == 0) continue;
                    const int plane = last_in_block[k] + (along[k] > 0 ? 1 : 0);
                    const double t = (lower[k] + plane * cell_size_[k] - from[k]) / along[k];
                    if (t < block_exit) block_exit = t, axis = k;
                }
                for (int k = 0; k < 3; ++k)
                    while (k != axis && cell_of[k] != last_in_block[k] &&
                           (across[k] < block_exit || (across[k] == block_exit && k < axis))) {
                        cell_of[k] += along[k] > 0 ? 1 : -1;
                        across[k] = next_plane(k);
                    }
                cell_of[axis] = last_in_block[axis];
                across[axis] = block_exit;
            }
            const double leave = std::min(across[axis], t1);
            cell_of[axis] += along[axis] > 0 ? 1 : -1;
            if (!(leave < t1) || cell_of[axis] < 0 || cell_of[axis] >= kCellsPerAxis) break;
            across[axis] = next_plane(axis);
            enter = std::max(enter, leave);
        }
        if (in_run && !add_run(run_start, t1)) return false;
        return !pending || visit(pending_lo, pending_hi);
    }

private:
    static constexpr int kBlock = 4, kBlocksPerAxis = kCellsPerAxis / kBlock,
                         kBlocks = kBlocksPerAxis * kBlocksPerAxis * kBlocksPerAxis;
    struct CellIndex {
        int i, j, l;
    };
    // The cell's bit in its block's word, and its block's index. Cell indices lie in [0, kCellsPerAxis): unsigned,
    // the divisions and remainders are shifts and masks.
    static int bit(CellIndex c) {
        const unsigned i = c.i, j = c.j, l = c.l;
        return int(((i % kBlock) * kBlock + j % kBlock) * kBlock + l % kBlock);
    }
    static int block_of(CellIndex c) {
        const unsigned i = c.i, j = c.j, l = c.l;
        return int(((i / kBlock) * kBlocksPerAxis + j / kBlock) * kBlocksPerAxis + l / kBlock);
    }

    // The surface bits of the block that holds cell c.
    template <class Range>
    std::uint64_t block_cells(CellIndex c, const Range& range) const {
        const int block = block_of(c);
        if (known_[block].load(std::memory_order_acquire)) return cells_[block].load(std::memory_order_relaxed);
        const std::uint64_t cells = find_block({c.i / kBlock * kBlock, c.j / kBlock * kBlock, c.l / kBlock * kBlock}, range);
        cells_[block].store(cells, std::memory_order_relaxed);
        known_[block].store(true, std::memory_order_release);
        return cells;
    }

    template <class Range>
    std::uint64_t find_block(CellIndex first, const Range& range) const {
        const auto can_hold_surface = [&](CellIndex from, int cells) {
            const IntervalBox lower = cell(from), upper = cell({from.i + cells - 1, from.j + cells - 1, from.l + cells - 1});
            const Interval g = range(IntervalBox{{lower.x.lo, upper.x.hi}, {lower.y.lo, upper.y.hi}, {lower.z.lo, upper.z.hi}});
            return !(g.lo > 0 || g.hi < 0);
        };
        std::uint64_t cells = 0;
        if (!can_hold_surface(first, kBlock)) return cells;
        for (int i = 0; i < kBlock; ++i)
            for (int j = 0; j < kBlock; ++j)
                for (int l = 0; l < kBlock; ++l)
                    if (can_hold_surface({first.i + i, first.j + j, first.l + l}, 1)) cells |= std::uint64_t(1) << bit({i, j, l});
        return cells;
    }

    IntervalBox cell(CellIndex c) const {
        const auto side = [&](int k, int at) {
            return Interval{box_[k].lo + at * cell_size_[k], at + 1 == kCellsPerAxis ? box_[k].hi : box_[k].lo + (at + 1) * cell_size_[k]};
        };
        return {side(0, c.i), side(1, c.j), side(2, c.l)};
    }

    IntervalBox box_;
    double cell_size_[3] = {0, 0, 0};
    // A block's 64 cells are the bits of one word, valid once its flag is set.
    mutable std::array<std::atomic<std::uint64_t>, kBlocks> cells_{};
    mutable std::array<std::atomic<bool>, kBlocks> known_{};
};

}  // namespace isotrace
