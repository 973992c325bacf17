#pragma once
// The cells of a uniform grid over a deformed superquadric's box that can hold its surface: those where the interval
// range of g contains zero. Elsewhere g keeps one sign throughout a cell, and (g being continuous) throughout any
// chain of such cells, so a ray needs searching only along its runs of shell cells: rays that pass the object
// through its box's empty corners cost a walk through the grid. Each shell cell also keeps g at its centre and bounds
// of g's gradient over it (ShellCellBounds), which settle most of a ray's stretch through the cell without walking it
// back through the deformations.
//
// The grid is found as rays need it, a block of 4³ cells at a time (the block first, its cells only when the block
// can hold the surface): a scene of many deformed superquadrics, each seen by a few pixels, does not pay for
// grids no ray walks. Threads that meet an unknown block at once both find it, with the same answer; the first to
// publish it (compare-and-swap) wins, the others free theirs. Blocks without surface cells share one empty block.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>

#include "geometry/superquadric/shell_cell_bounds.h"
#include "renderer/math/interval.h"
#include "renderer/math/vec3.h"

namespace isotrace {

class SurfaceShell {
public:
    static constexpr int kCellsPerAxis = 32;

private:
    static constexpr int kBlock = 4, kBlocksPerAxis = kCellsPerAxis / kBlock,
                         kBlocks = kBlocksPerAxis * kBlocksPerAxis * kBlocksPerAxis;
    // What a block keeps of a shell cell's ShellCellBounds (the centre follows from the cell): the gradient's
    // bounds as floats rounded outward, an unknown gradient as a NaN value.
    struct CellEntry {
        double value = std::numeric_limits<double>::quiet_NaN();
        float gradient_lo[3] = {0, 0, 0}, gradient_hi[3] = {0, 0, 0};

        static CellEntry of(const ShellCellBounds& bounds) {
            CellEntry entry;
            if (!bounds.known) return entry;
            entry.value = bounds.value;
            for (int k = 0; k < 3; ++k) {
                entry.gradient_lo[k] = rounded_down(bounds.gradient[k].lo);
                entry.gradient_hi[k] = -rounded_down(-bounds.gradient[k].hi);
            }
            return entry;
        }
        ShellCellBounds bounds(const Vec3d& centre) const {
            ShellCellBounds bounds;
            if (std::isnan(value)) return bounds;
            bounds.known = true, bounds.centre = centre, bounds.value = value;
            for (int k = 0; k < 3; ++k) bounds.gradient[k] = {gradient_lo[k], gradient_hi[k]};
            return bounds;
        }
        static float rounded_down(double v) {
            const float f = float(v);
            return double(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
        }
    };
    // What is known of g over a block's 64 cells, where they can hold the surface.
    struct Block {
        std::array<CellEntry, kBlock * kBlock * kBlock> entries{};
    };
    // A block, once found, and which of its cells can hold the surface (the bits of one word). The words lie side
    // by side with the pointers, so that the walk reads them without touching the blocks, which lie apart on the
    // heap: it reaches a block only for the entry of a surface cell.
    struct Slot {
        std::atomic<const Block*> block{nullptr};
        std::atomic<std::uint64_t> cells{0};  // stored before `block` is published
    };
    struct FoundBlock {
        const Block* block;
        std::uint64_t cells;
    };

public:
    // The most a shell takes on the heap, once rays have found every block.
    static constexpr std::size_t kMostHeapBytes = std::size_t(kBlocks) * sizeof(Block);

    SurfaceShell() = default;
    explicit SurfaceShell(const IntervalBox& box) : box_(box) {
        for (int k = 0; k < 3; ++k) cell_size_[k] = box[k].width() / kCellsPerAxis;
    }
    SurfaceShell(const SurfaceShell& other) { *this = other; }
    SurfaceShell& operator=(const SurfaceShell& other) {
        if (this == &other) return *this;
        release();
        box_ = other.box_;
        std::copy(std::begin(other.cell_size_), std::end(other.cell_size_), std::begin(cell_size_));
        for (int b = 0; b < kBlocks; ++b) {
            const Block* block = other.slots_[b].block.load(std::memory_order_acquire);
            slots_[b].cells.store(other.slots_[b].cells.load(std::memory_order_relaxed), std::memory_order_relaxed);
            slots_[b].block.store(block && block != empty_block() ? new Block(*block) : block, std::memory_order_relaxed);
        }
        return *this;
    }
    ~SurfaceShell() { release(); }

    // Calls visit(a, b, bounds) for the stretches [a, b] of origin + t·direction within [t0, t1] (the part of the
    // line inside the box) through shell cells, in increasing t, until it returns false (then returns false), with
    // what is known of g over each cell (ShellCellBounds). `range(box)` contains g over a box inside the grid's;
    // `cell_bounds(box, centre)` tells g at a cell's centre and bounds its gradient over the cell (enlarged a little).
    // The stretches through a run of consecutive shell cells meet end to end; each run is widened by 10⁻⁹ of
    // [t0, t1] at both ends (its first and last cells' stretches) so that the rounding of the cell boundaries cannot
    // cut a crossing off, and runs that then touch are joined.
    template <class Range, class CellBounds, class Visit>
    bool visit_cells(const Vec3d& origin, const Vec3d& direction, double t0, double t1, const Range& range,
                     const CellBounds& cell_bounds, Visit&& visit) const {
        const double pad = 1e-9 * (t1 - t0);
        // The last cell's stretch waits until the next one shows whether the run goes on.
        bool pending = false;
        double pending_lo = 0, pending_hi = 0;
        ShellCellBounds pending_bounds;
        const auto flush = [&](double end) {
            pending = false;
            return visit(pending_lo, end, pending_bounds);
        };
        const auto add_cell = [&](double a, double b, const ShellCellBounds& bounds, bool opens_run) {
            if (opens_run) {
                a = std::max(t0, a - pad);
                if (pending) {  // the last run ends here, padded, unless the two touch once padded
                    const double padded = std::min(t1, pending_hi + pad);
                    if (a <= padded) a = pending_hi;
                    if (!flush(a <= padded ? pending_hi : padded)) return false;
                }
            } else if (pending && !flush(pending_hi)) {
                return false;
            }
            pending = true, pending_lo = a, pending_hi = b, pending_bounds = bounds;
            return true;
        };
        // Cell by cell. Per axis in arrays, indexed only by constants once the loops over the three axes are unrolled
        // (the axis that moves is chosen by selects, not by an index), so that they stay in registers: an index
        // stored and loaded again, and branches on which plane comes first, were most of the walk's time — more than
        // stepping past blocks without surface cells at once saved, which the walk no longer does.
        const Vec3d start = origin + direction * t0;
        const double from[3] = {origin.x, origin.y, origin.z}, along[3] = {direction.x, direction.y, direction.z},
                     lower[3] = {box_.x.lo, box_.y.lo, box_.z.lo}, first[3] = {start.x, start.y, start.z};
        int cell_of[3];
        for (int k = 0; k < 3; ++k)
            cell_of[k] = std::clamp(int(std::floor((first[k] - lower[k]) / cell_size_[k])), 0, kCellsPerAxis - 1);
        // Where the line leaves the current cell across axis k's next plane. A product with the reciprocal: a division
        // would stand on the walk's chain of dependent steps.
        const double inverse[3] = {1 / along[0], 1 / along[1], 1 / along[2]};
        const auto next_plane = [&](int k) {
            const int plane = cell_of[k] + (along[k] > 0 ? 1 : 0);
            const double t = (lower[k] + plane * cell_size_[k] - from[k]) * inverse[k];
            return along[k] == 0 ? std::numeric_limits<double>::infinity() : t;
        };
        double enter = t0;
        bool in_run = false;
        // Only the axis whose plane was crossed moves on: the others keep their next plane.
        double across[3] = {next_plane(0), next_plane(1), next_plane(2)};
        // The surface bits and cell bounds of the block the walk is in, looked up again only when it enters another.
        int block_index = -1;
        FoundBlock block{};
        for (int step = 0; step <= 3 * kCellsPerAxis; ++step) {  // a line crosses at most 3·n cells
            const CellIndex cell{cell_of[0], cell_of[1], cell_of[2]};
            if (const int index = block_of(cell); index != block_index)
                block_index = index, block = find_block(index, cell, range, cell_bounds);
            const bool surface = (block.cells >> bit(cell)) & 1;
            const int axis = across[0] <= across[1] && across[0] <= across[2] ? 0 : across[1] <= across[2] ? 1 : 2;
            // across[axis], the least (whichever axis a tie went to).
            const double leave = std::min({across[0], across[1], across[2], t1});
            if (surface && !add_cell(enter, std::max(enter, leave), block.block->entries[bit(cell)].bounds(centre(cell)), !in_run))
                return false;
            in_run = surface;
            bool off_grid = false;
            for (int k = 0; k < 3; ++k) {
                const bool moves = k == axis;
                cell_of[k] += moves ? (along[k] > 0 ? 1 : -1) : 0;
                off_grid |= unsigned(cell_of[k]) >= unsigned(kCellsPerAxis);
                across[k] = moves ? next_plane(k) : across[k];
            }
            if (!(leave < t1) || off_grid) break;
            enter = std::max(enter, leave);
        }
        return !pending || flush(in_run ? t1 : std::min(t1, pending_hi + pad));
    }

private:
    struct CellIndex {
        int i, j, l;
    };
    // Shared by every block without surface cells, which need no bounds.
    static const Block* empty_block() {
        static const Block block;
        return &block;
    }

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

    // The block with index `index`, which holds cell c: once known, read inline; found out of line when first asked
    // for (the walk asks at every block it enters, and nearly always the block is known).
    template <class Range, class CellBounds>
    FoundBlock find_block(int index, CellIndex c, const Range& range, const CellBounds& cell_bounds) const {
        const Slot& slot = slots_[index];
        if (const Block* known = slot.block.load(std::memory_order_acquire))
            return {known, slot.cells.load(std::memory_order_relaxed)};
        return make_block(index, c, range, cell_bounds);
    }
    template <class Range, class CellBounds>
    [[gnu::noinline]] FoundBlock make_block(int index, CellIndex c, const Range& range,
                                            const CellBounds& cell_bounds) const {
        Slot& slot = slots_[index];
        const CellIndex first{c.i / kBlock * kBlock, c.j / kBlock * kBlock, c.l / kBlock * kBlock};
        const auto can_hold_surface = [&](CellIndex from, int cells) {
            const IntervalBox lower = cell(from), upper = cell({from.i + cells - 1, from.j + cells - 1, from.l + cells - 1});
            const Interval g = range(IntervalBox{{lower.x.lo, upper.x.hi}, {lower.y.lo, upper.y.hi}, {lower.z.lo, upper.z.hi}});
            return !(g.lo > 0 || g.hi < 0);
        };
        const Block* found = empty_block();
        std::uint64_t cells = 0;
        if (can_hold_surface(first, kBlock)) {
            Block* block = new Block;
            for (int i = 0; i < kBlock; ++i)
                for (int j = 0; j < kBlock; ++j)
                    for (int l = 0; l < kBlock; ++l) {
                        const CellIndex at{first.i + i, first.j + j, first.l + l};
                        if (!can_hold_surface(at, 1)) continue;
                        cells |= std::uint64_t(1) << bit(at);
                        IntervalBox around = cell(at);  // enlarged by far more than a run's padding
                        for (int k = 0; k < 3; ++k) around[k] = {around[k].lo - 1e-6 * cell_size_[k], around[k].hi + 1e-6 * cell_size_[k]};
                        block->entries[bit(at)] = CellEntry::of(cell_bounds(around, centre(at)));
                    }
            if (cells != 0) found = block;
            else delete block;
        }
        // A thread that loses the race stores the same word.
        slot.cells.store(cells, std::memory_order_relaxed);
        const Block* expected = nullptr;
        if (slot.block.compare_exchange_strong(expected, found, std::memory_order_acq_rel)) return {found, cells};
        if (found != empty_block()) delete found;
        return {expected, cells};
    }

    IntervalBox cell(CellIndex c) const {
        const auto side = [&](int k, int at) {
            return Interval{box_[k].lo + at * cell_size_[k], at + 1 == kCellsPerAxis ? box_[k].hi : box_[k].lo + (at + 1) * cell_size_[k]};
        };
        return {side(0, c.i), side(1, c.j), side(2, c.l)};
    }

    Vec3d centre(CellIndex c) const {
        const IntervalBox box = cell(c);
        return (box.lower() + box.upper()) * 0.5;
    }

    void release() {
        for (Slot& slot : slots_) {
            const Block* block = slot.block.exchange(nullptr, std::memory_order_acq_rel);
            if (block != empty_block()) delete block;
        }
    }

    IntervalBox box_;
    double cell_size_[3] = {0, 0, 0};
    mutable std::array<Slot, kBlocks> slots_{};
};

}  // namespace isotrace
