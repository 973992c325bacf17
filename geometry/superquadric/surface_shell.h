#pragma once
// The cells of a uniform grid over a deformed superquadric's box that can hold its surface: those where the interval
// range of g contains zero, and so do the cell's own bounds (below), which are far tighter where a twist or a bend
// turns the cell. Elsewhere g keeps one sign throughout a cell, and (g being continuous) throughout any
// chain of such cells, so a ray needs searching only along its runs of shell cells: rays that pass the object
// through its box's empty corners cost a walk through the grid. Each shell cell also keeps g at its centre and bounds
// of g's gradient over it (ShellCellBounds), which settle most of a ray's stretch through the cell without walking it
// back through the deformations.
//
// The grid is found as rays need it, a block of 4³ cells at a time (the block first, its cells only when the block
// can hold the surface): a scene of many deformed superquadrics, each seen by a few pixels, does not pay for
// grids no ray walks. Threads that meet an unknown block at once both find it, with the same answer; the first to
// publish it (compare-and-swap) wins, the others free theirs. Blocks without surface cells share one empty block.
//
// A shell cell whose own bounds are unknown — g's gradient is unbounded in it, as the gauge's is for p < 1 on the
// coordinate planes the cell's preimage touches, the creases of a star-like shape — is split into eighths, each with
// its own bounds or sign: most eighths lie away from the crease, and a ray's stretch through them is settled by their
// bounds where the whole cell would have taken a walk through the deformations. A ray's runs then hold the stretches
// through the eighths, not through the whole cell.
//
// The cells without surface keep g's sign too (one bit each): the walk hands the search a run of shell cells at a
// time with the sign on either side of it, so that an occlusion query settles a run that leads from outside to inside
// (a ray through another object) with no value of g at all.
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

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
    // A split cell's eighths (eighth_box): which can hold the surface, g's sign over the others, and where the
    // entries of the first lie among the block's eighth_entries (theirs follow, in the order of their bits).
    struct Eighths {
        std::uint8_t cells = 0, inside = 0;
        std::uint16_t first = 0;
    };
    // What is known of g over a block's surface cells and the eighths of its split cells that can hold the surface,
    // each in the order of their bits: only those, as a rule a quarter of the block's cells and half of a split
    // cell's eighths (the others' entries would be memory no walk reads).
    struct Block {
        std::vector<CellEntry> entries;
        std::vector<Eighths> eighths;
        std::vector<CellEntry> eighth_entries;
    };
    // A block, once found, and which of its cells can hold the surface (the bits of one word). The words lie side
    // by side with the pointers, so that the walk reads them without touching the blocks, which lie apart on the
    // heap: it reaches a block only for the entry of a surface cell.
    struct Slot {
        std::atomic<const Block*> block{nullptr};
        std::atomic<std::uint64_t> cells{0};   // stored before `block` is published
        std::atomic<std::uint64_t> inside{0};  // the cells without surface where g < 0; stored before `block` too
        std::atomic<std::uint64_t> split{0};   // the surface cells split into eighths; stored before `block` too
    };
    struct FoundBlock {
        const Block* block;
        std::uint64_t cells, inside, split;
    };
    struct CellIndex {
        int i, j, l;
    };
    static constexpr int kWholeCell = -1;  // a stretch through a cell, not one of its eighths

public:
    // The most cells of a block that are split (the first in the order of their bits), for a bound on the heap: the
    // star-like shapes' blocks hold up to a few dozen cells without bounds.
    static constexpr int kMostSplitPerBlock = 32;
    // The most a shell takes on the heap, once rays have found every block.
    static constexpr std::size_t kMostHeapBytes =
        std::size_t(kBlocks) *
        (sizeof(Block) + kBlock * kBlock * kBlock * sizeof(CellEntry) +
         kMostSplitPerBlock * (sizeof(Eighths) + 8 * sizeof(CellEntry)));

    // g's sign next to a run, where a cell without surface lies there: such a cell's g keeps one sign, which holds
    // at the run's padded end (inside that cell, or inside the cells without surface that follow it, which share
    // its sign: neighbours across a face cannot keep opposite signs).
    enum class Side : std::uint8_t { Unknown, Outside, Inside };

    // A run of shell cells along a line: its cells' stretches (or, through a split cell, its eighths'), end to end,
    // from lo() to hi(), and g's sign before and after it.
    class Run {
    public:
        Side before = Side::Unknown, after = Side::Unknown;

        std::size_t size() const { return count_; }
        double lo() const { return lo_; }
        double hi() const { return ends_[count_ - 1]; }
        // Stretch k and what is known of g over its cell or eighth.
        double start(std::size_t k) const { return k == 0 ? lo_ : ends_[k - 1]; }
        double end(std::size_t k) const { return ends_[k]; }
        ShellCellBounds bounds(std::size_t k) const {
            return entries_[k]->bounds(shell_->centre(cells_[k], eighths_[k]));
        }

    private:
        friend class SurfaceShell;
        // A line crosses at most 3·n cells, and 3·2n eighths.
        static constexpr std::size_t kMostStretches = 6 * kCellsPerAxis + 1;

        const SurfaceShell* shell_ = nullptr;
        double lo_ = 0;
        std::size_t count_ = 0;
        double ends_[kMostStretches];
        const CellEntry* entries_[kMostStretches];
        CellIndex cells_[kMostStretches];
        std::int8_t eighths_[kMostStretches];  // kWholeCell, or the stretch's eighth of its cell
    };

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
            slots_[b].inside.store(other.slots_[b].inside.load(std::memory_order_relaxed), std::memory_order_relaxed);
            slots_[b].split.store(other.slots_[b].split.load(std::memory_order_relaxed), std::memory_order_relaxed);
            slots_[b].block.store(block && block != empty_block() ? new Block(*block) : block, std::memory_order_relaxed);
        }
        return *this;
    }
    ~SurfaceShell() { release(); }

    // Calls visit(run) for the runs of shell cells (Run) along origin + t·direction within [t0, t1] (the part of the
    // line inside the box), in increasing t, until it returns false (then returns false). `range(box)` contains g
    // over a box inside the grid's; `cell_bounds(box, centre)` tells g at a cell's centre and bounds its gradient over
    // the cell (enlarged a little). Each run is widened by 10⁻⁹ of [t0, t1] at both ends so that the rounding of the
    // cell boundaries cannot cut a crossing off, and runs that then touch are joined (the gap between them goes to
    // the later run's first cell).
    template <class Range, class CellBounds, class Visit>
    bool visit_runs(const Vec3d& origin, const Vec3d& direction, double t0, double t1, const Range& range,
                    const CellBounds& cell_bounds, Visit&& visit) const {
        const double pad = 1e-9 * (t1 - t0);
        // The run being gathered, handed over once the walk shows where it ends (a gap after it that no later run
        // can bridge, or the end of the line); g's sign over the cells without surface last walked.
        Run run;
        run.shell_ = this;
        Side gap = Side::Unknown;
        double gap_from = t0;  // where the last run's cells end, padded
        const auto hand_over = [&](Side after, double hi) {
            run.after = after;
            run.ends_[run.count_ - 1] = hi;
            const bool more = visit(std::as_const(run));
            run.count_ = 0;
            return more;
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
        // Where the line leaves the current cell across axis k's next plane: the first plane from its position, each
        // later one a cell's width in t further (`width`), so that the walk's chain of dependent steps holds one
        // addition per step, not a conversion and two products. The sums drift by a few ulps over a line, far less
        // than a run's padding.
        double across[3], width[3];
        for (int k = 0; k < 3; ++k) {
            const double inverse = 1 / along[k];
            const int plane = cell_of[k] + (along[k] > 0 ? 1 : 0);
            across[k] = along[k] == 0 ? std::numeric_limits<double>::infinity()
                                      : (lower[k] + plane * cell_size_[k] - from[k]) * inverse;
            width[k] = cell_size_[k] * std::abs(inverse);
        }
        double enter = t0;
        bool in_run = false;
        // A stretch [lo, hi] of a surface cell or eighth joins the run, opening one after a gap (joined to the last
        // run if the two touch once padded: the gap goes to this stretch); one of a cell or eighth without surface,
        // where g has the sign `side`, ends the run.
        const auto surface_stretch = [&](double lo, double hi, const CellEntry* entry, CellIndex cell, int eighth) {
            if (!in_run) {
                const double a = std::max(t0, lo - pad);
                if (run.count_ > 0 && a > gap_from && !hand_over(gap, gap_from)) return false;
                if (run.count_ == 0) run.lo_ = a, run.before = gap;
            }
            run.ends_[run.count_] = std::max(lo, hi);
            run.entries_[run.count_] = entry;
            // The search reads the entry once the run is handed over, steps later: fetched now, its cache miss (the
            // blocks of a scene's shells outgrow a core's cache) overlaps the walk instead of stalling the search.
            __builtin_prefetch(entry);
            run.cells_[run.count_] = cell;
            run.eighths_[run.count_] = std::int8_t(eighth);
            ++run.count_;
            in_run = true;
            return true;
        };
        const auto gap_stretch = [&](double hi, Side side) {
            gap = side;
            if (in_run) gap_from = std::min(t1, run.ends_[run.count_ - 1] + pad);
            in_run = false;
            // Once the gap is longer than both pads no later run can join the last one: it is handed over here,
            // not when the next run opens, so that a search that ends in it does not walk the gap first.
            return !(run.count_ > 0 && hi - pad > gap_from) || hand_over(gap, gap_from);
        };
        // The axis across which the line leaves the current cell (whichever a tie went to), and where: across[axis].
        const auto next_axis = [&] {
            return across[0] <= across[1] && across[0] <= across[2] ? 0 : across[1] <= across[2] ? 1 : 2;
        };
        const auto leaving = [&] { return std::min({across[0], across[1], across[2], t1}); };
        int step = 0;  // a line crosses at most 3·n cells
        // Into the next cell across `axis`, which the line reaches at `leave`: false where the line ends or leaves
        // the grid there.
        const auto step_across = [&](int axis, double leave) {
            bool off_grid = false;
            for (int k = 0; k < 3; ++k) {
                const bool moves = k == axis;
                cell_of[k] += moves ? (along[k] > 0 ? 1 : -1) : 0;
                off_grid |= unsigned(cell_of[k]) >= unsigned(kCellsPerAxis);
                across[k] = moves ? across[k] + width[k] : across[k];  // the others keep their next plane
            }
            if (!(leave < t1) || off_grid || ++step > 3 * kCellsPerAxis) return false;
            enter = std::max(enter, leave);
            return true;
        };
        while (true) {
            const CellIndex cell{cell_of[0], cell_of[1], cell_of[2]};
            // The block's words are read at every step: they lie side by side in the slots, and a branch on whether
            // the walk entered another block (every few steps, in no pattern) cost more than the loads.
            const FoundBlock block = find_block(block_of(cell), cell, range, cell_bounds);
            const int at = bit(cell);
            int axis = next_axis();
            double leave = leaving();
            if (!((block.cells >> at) & 1)) {
                const bool inside = (block.inside >> at) & 1;
                if (!gap_stretch(leave, inside ? Side::Inside : Side::Outside)) return false;
                if (run.count_ == 0) {
                    // Nothing gathered waits for the gap's end: the cells without surface that follow, of the same
                    // sign, need nothing but the walk's steps, taken in a loop of their own, small enough to keep
                    // its state in registers (most of a walk's steps: those of a ray that has left the surface).
                    // The first cell of another kind is handled as any cell, at the top.
                    bool more;
                    while ((more = step_across(axis, leave))) {
                        const CellIndex next{cell_of[0], cell_of[1], cell_of[2]};
                        const Slot& slot = slots_[block_of(next)];
                        const int next_at = bit(next);
                        if (!slot.block.load(std::memory_order_acquire) ||
                            ((slot.cells.load(std::memory_order_relaxed) >> next_at) & 1) ||
                            bool((slot.inside.load(std::memory_order_relaxed) >> next_at) & 1) != inside)
                            break;
                        axis = next_axis();
                        leave = leaving();
                    }
                    if (!more) break;
                    continue;
                }
            } else if (!((block.split >> at) & 1)) {
                if (!surface_stretch(enter, leave, &cell_entry(block, at), cell, kWholeCell)) return false;
            } else {
                // Through the eighths: cut where the line crosses the cell's middle planes, half a cell's width in t
                // before it leaves across each; each piece's eighth is that of its middle.
                const Eighths& eighths = split_eighths(block, at);
                double cuts[4];
                int count = 0;
                for (int k = 0; k < 3; ++k) {
                    const double middle = across[k] - 0.5 * width[k];
                    if (!(middle > enter && middle < leave)) continue;
                    int i = count++;
                    for (; i > 0 && cuts[i - 1] > middle; --i) cuts[i] = cuts[i - 1];
                    cuts[i] = middle;
                }
                cuts[count++] = leave;
                const IntervalBox box = this->cell(cell);
                double lo = enter;
                for (int c = 0; c < count; ++c) {
                    const double middle = 0.5 * (lo + cuts[c]);
                    int eighth = 0;
                    for (int k = 0; k < 3; ++k)
                        eighth |= int(from[k] + along[k] * middle >= 0.5 * (box[k].lo + box[k].hi)) << (2 - k);
                    const bool more =
                        (eighths.cells >> eighth) & 1
                            ? surface_stretch(lo, cuts[c], &eighth_entry(block, eighths, eighth), cell, eighth)
                            : gap_stretch(cuts[c], (eighths.inside >> eighth) & 1 ? Side::Inside : Side::Outside);
                    if (!more) return false;
                    lo = std::max(lo, cuts[c]);
                }
            }
            if (!step_across(axis, leave)) break;
        }
        if (run.count_ == 0) return true;
        return in_run ? hand_over(Side::Unknown, t1) : hand_over(gap, gap_from);
    }

    // g's sign at a point of the box as the cell that holds it tells (its block found as the walk finds it, with the
    // same `range` and `cell_bounds`): Unknown in a surface cell, and within a millionth of a cell of its faces, where
    // rounding might take the point to the neighbouring cell.
    template <class Range, class CellBounds>
    Side side_at(const Vec3d& point, const Range& range, const CellBounds& cell_bounds) const {
        int at_cell[3];
        for (int k = 0; k < 3; ++k) {
            const double along = (point[k] - box_[k].lo) / cell_size_[k], whole = std::floor(along);
            if (!(whole >= 0 && whole < kCellsPerAxis) || along - whole < 1e-6 || along - whole > 1 - 1e-6)
                return Side::Unknown;
            at_cell[k] = int(whole);
        }
        const CellIndex cell{at_cell[0], at_cell[1], at_cell[2]};
        const FoundBlock block = find_block(block_of(cell), cell, range, cell_bounds);
        const int at = bit(cell);
        if (!((block.cells >> at) & 1)) return (block.inside >> at) & 1 ? Side::Inside : Side::Outside;
        if (!((block.split >> at) & 1)) return Side::Unknown;
        int eighth = 0;
        for (int k = 0; k < 3; ++k) {
            const double half = (point[k] - box_[k].lo) / cell_size_[k] - at_cell[k];
            if (std::abs(half - 0.5) < 1e-6) return Side::Unknown;
            eighth |= int(half >= 0.5) << (2 - k);
        }
        const Eighths& eighths = split_eighths(block, at);
        if ((eighths.cells >> eighth) & 1) return Side::Unknown;
        return (eighths.inside >> eighth) & 1 ? Side::Inside : Side::Outside;
    }

private:
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

    // A surface cell's entry, a split cell's eighths and an eighth's entry in a found block, each kept in the order of
    // its bits (the cells' word, the eighths' byte): the place of bit `at` among the bits set in `word`.
    static std::size_t rank(std::uint64_t word, int at) {
        return std::size_t(std::popcount(word & ((std::uint64_t(1) << at) - 1)));
    }
    static const CellEntry& cell_entry(const FoundBlock& block, int at) {
        return block.block->entries[rank(block.cells, at)];
    }
    static const Eighths& split_eighths(const FoundBlock& block, int at) {
        return block.block->eighths[rank(block.split, at)];
    }
    static const CellEntry& eighth_entry(const FoundBlock& block, const Eighths& eighths, int eighth) {
        return block.block->eighth_entries[eighths.first + rank(eighths.cells, eighth)];
    }

    // The block with index `index`, which holds cell c: once known, read inline; found out of line when first asked
    // for (the walk asks at every step, and nearly always the block is known).
    template <class Range, class CellBounds>
    FoundBlock find_block(int index, CellIndex c, const Range& range, const CellBounds& cell_bounds) const {
        const Slot& slot = slots_[index];
        if (const Block* known = slot.block.load(std::memory_order_acquire))
            return {known, slot.cells.load(std::memory_order_relaxed), slot.inside.load(std::memory_order_relaxed),
                    slot.split.load(std::memory_order_relaxed)};
        return make_block(index, c, range, cell_bounds);
    }
    template <class Range, class CellBounds>
    [[gnu::noinline]] FoundBlock make_block(int index, CellIndex c, const Range& range,
                                            const CellBounds& cell_bounds) const {
        Slot& slot = slots_[index];
        const CellIndex first{c.i / kBlock * kBlock, c.j / kBlock * kBlock, c.l / kBlock * kBlock};
        // g's range over the cells from `from` on, `cells` of them along each axis.
        const auto range_over = [&](CellIndex from, int cells) {
            const IntervalBox lower = cell(from), upper = cell({from.i + cells - 1, from.j + cells - 1, from.l + cells - 1});
            return range(IntervalBox{{lower.x.lo, upper.x.hi}, {lower.y.lo, upper.y.hi}, {lower.z.lo, upper.z.hi}});
        };
        const Block* found = empty_block();
        std::uint64_t cells = 0, inside = 0, split = 0;
        if (const Interval whole = range_over(first, kBlock); !can_hold_surface(whole)) {
            inside = whole.hi < 0 ? ~std::uint64_t(0) : 0;
        } else {
            Block* block = new Block;
            for (int i = 0; i < kBlock; ++i)
                for (int j = 0; j < kBlock; ++j)
                    for (int l = 0; l < kBlock; ++l) {
                        const CellIndex at{first.i + i, first.j + j, first.l + l};
                        if (const Interval g = range_over(at, 1); !can_hold_surface(g)) {
                            inside |= std::uint64_t(g.hi < 0) << bit(at);
                            continue;
                        }
                        // The cell's own bounds (its centre's value, its gradient's bounds) are far tighter than
                        // `range` where a twist or a bend turns the cell: they clear many cells it could not.
                        const OwnBounds own = own_bounds(enlarged(cell(at)), centre(at, kWholeCell), cell_bounds);
                        if (own.clears) {
                            inside |= std::uint64_t(own.inside) << bit(at);
                            continue;
                        }
                        cells |= std::uint64_t(1) << bit(at);
                        block->entries.push_back(CellEntry::of(own.bounds));
                        if (own.bounds.known || block->eighths.size() == kMostSplitPerBlock) continue;
                        if (find_eighths(at, range, cell_bounds, *block)) split |= std::uint64_t(1) << bit(at);
                    }
            if (cells != 0) {
                block->entries.shrink_to_fit();
                block->eighths.shrink_to_fit();
                block->eighth_entries.shrink_to_fit();
                found = block;
            } else {
                delete block;
            }
        }
        // A thread that loses the race stores the same words.
        slot.cells.store(cells, std::memory_order_relaxed);
        slot.inside.store(inside, std::memory_order_relaxed);
        slot.split.store(split, std::memory_order_relaxed);
        const Block* expected = nullptr;
        if (slot.block.compare_exchange_strong(expected, found, std::memory_order_acq_rel))
            return {found, cells, inside, split};
        if (found != empty_block()) delete found;
        return {expected, cells, inside, split};
    }

    // What is known over a surface cell's eighths, found as make_block finds a cell's, kept in `block` where that
    // settles some of them (their own bounds, or a sign): whether it does.
    template <class Range, class CellBounds>
    bool find_eighths(CellIndex at, const Range& range, const CellBounds& cell_bounds, Block& block) const {
        Eighths eighths{.first = std::uint16_t(block.eighth_entries.size())};
        std::array<CellEntry, 8> entries;
        bool settles = false;
        for (int eighth = 0; eighth < 8; ++eighth) {
            const IntervalBox around = enlarged(eighth_box(at, eighth));
            if (const Interval g = range(around); !can_hold_surface(g)) {
                eighths.inside |= std::uint8_t(int(g.hi < 0) << eighth);
                settles = true;
                continue;
            }
            const OwnBounds own = own_bounds(around, centre(at, eighth), cell_bounds);
            settles = settles || own.bounds.known;
            if (own.clears) {
                eighths.inside |= std::uint8_t(int(own.inside) << eighth);
                continue;
            }
            entries[std::popcount(eighths.cells)] = CellEntry::of(own.bounds);
            eighths.cells |= std::uint8_t(1 << eighth);
        }
        if (!settles) return false;
        block.eighths.push_back(eighths);
        block.eighth_entries.insert(block.eighth_entries.end(), entries.begin(),
                                    entries.begin() + std::popcount(eighths.cells));
        return true;
    }

    IntervalBox cell(CellIndex c) const {
        const auto side = [&](int k, int at) {
            return Interval{box_[k].lo + at * cell_size_[k], at + 1 == kCellsPerAxis ? box_[k].hi : box_[k].lo + (at + 1) * cell_size_[k]};
        };
        return {side(0, c.i), side(1, c.j), side(2, c.l)};
    }

    static bool can_hold_surface(const Interval& g) { return !(g.lo > 0 || g.hi < 0); }

    // A cell's or an eighth's own bounds over `around` (it, enlarged), and whether they clear it of the surface after
    // all, with g's sign there.
    struct OwnBounds {
        ShellCellBounds bounds;
        bool clears = false, inside = false;
    };
    template <class CellBounds>
    static OwnBounds own_bounds(const IntervalBox& around, const Vec3d& centre, const CellBounds& cell_bounds) {
        OwnBounds own{cell_bounds(around, centre)};
        if (!own.bounds.known) return own;
        const Interval g = own.bounds.range(around);
        own.clears = !can_hold_surface(g), own.inside = g.hi < 0;
        return own;
    }

    // A cell's eighth: the halves of its sides below or above their middles, as the bits 4, 2 and 1 of `eighth`
    // say for x, y and z.
    IntervalBox eighth_box(CellIndex c, int eighth) const {
        IntervalBox box = cell(c);
        for (int k = 0; k < 3; ++k) {
            const double middle = 0.5 * (box[k].lo + box[k].hi);
            box[k] = (eighth >> (2 - k)) & 1 ? Interval{middle, box[k].hi} : Interval{box[k].lo, middle};
        }
        return box;
    }
    // A box enlarged by far more than a run's padding, for the bounds of the cell or eighth it is.
    IntervalBox enlarged(IntervalBox box) const {
        for (int k = 0; k < 3; ++k) box[k] = {box[k].lo - 1e-6 * cell_size_[k], box[k].hi + 1e-6 * cell_size_[k]};
        return box;
    }
    Vec3d centre(CellIndex c, int eighth) const {
        const IntervalBox box = eighth == kWholeCell ? cell(c) : eighth_box(c, eighth);
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
