#pragma once
// BlobCells: space cut into disjoint boxes ("cells"), each listing every element whose support reaches into it.
// A cell is the unit of work of a blob ray: inside a cell the summed field is the sum over the cell's list, so a
// query of one cell needs nothing from any other query of the same ray — Embree traverses the cells (one user
// primitive each, front to back, culling beyond the nearest hit found) and each cell marches its stretch of the
// ray once (field_march.h). Like Mitsuba's sdfgrid voxels, but adaptive: a kd-tree splits space at the middle of
// its longest side until a cell lists few elements or is about as small as its elements' supports; each leaf
// box is then shrunk to the supports it lists (still inside its kd cell, so cells stay disjoint), and further, by
// restrict_to_surface, to where the surface may lie: a cell that is all inside or all outside is no ray primitive.
// The kd-tree itself is kept for point queries (field and normal at a point) and for walking a ray's cells in
// order (CSG).
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "geometry/implicit/metacube.h"

namespace isotrace {

class BlobCells {
public:
    struct Cell {
        // Closed box that rays march; cells overlap at most on their faces. Cells at or beyond
        // surface_cell_count() have none (lower > upper).
        Vec3d lower, upper;
        std::uint32_t first = 0, count = 0;  // its elements: element_ids()[first, first + count), ascending
    };

    // Cells over the supports of `elements` (the lists index into it).
    void build(std::span<const Metacube> elements);

    // The part of a cell's box where a ray may cross the surface (std::nullopt: nowhere), given the box and the
    // cell's elements; surface_region.h computes it for a blob group.
    using SurfaceRegion =
        std::function<std::optional<WorldBounds>(const WorldBounds&, std::span<const std::uint32_t>)>;
    // Shrinks every cell's box to its surface region and moves the cells without one to the end, where they keep
    // their lists for point queries but are no ray primitive. Cells are independent, so they are done in parallel.
    void restrict_to_surface(const SurfaceRegion& region);

    std::span<const Cell> cells() const { return cells_; }
    // Cells [0, surface_cell_count()) have a box to march: the ray primitives.
    std::uint32_t surface_cell_count() const { return surface_cells_; }
    std::span<const std::uint32_t> elements_of(const Cell& cell) const {
        return {element_ids_.data() + cell.first, cell.count};
    }
    std::span<const std::uint32_t> elements_of(std::uint32_t cell) const { return elements_of(cells_[cell]); }
    std::size_t memory_bytes() const;

    // The elements whose support may contain p: the list of the kd cell that holds p (empty outside the bounds
    // of every support).
    std::span<const std::uint32_t> elements_near(const Vec3d& p) const;

    // Calls visit(cell, t_enter, t_exit) for the kd cells that o + t·d meets within [t_min, t_max], in increasing
    // t (stretches of consecutive cells touch; gaps are empty space), with or without a surface region. Stops
    // early when visit returns false.
    template <class Visit>
    void walk(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max, Visit&& visit) const;

private:
    // An inner node splits at `split` along `axis` (0–2) into nodes `child` and `child + 1`; a leaf (axis 3)
    // holds cell `child`, or kNoCell when no support reaches into it.
    struct Node {
        double split = 0;
        std::uint32_t axis = 3;
        std::uint32_t child = kNoCell;
    };
    static constexpr std::uint32_t kNoCell = 0xFFFFFFFFu;
    static constexpr int kMaxDepth = 48;  // the traversal stack holds at most one pending node per level
    void build_node(std::span<const Metacube> elements, std::uint32_t node, const WorldBounds& box,
                    const std::vector<std::uint32_t>& ids, int depth);

    std::vector<Node> nodes_;
    std::vector<Cell> cells_;
    std::vector<std::uint32_t> element_ids_;
    WorldBounds root_{};  // the kd-tree's box: the bounds of every support
    std::uint32_t surface_cells_ = 0;
};

template <class Visit>
void BlobCells::walk(const Vec3d& origin, const Vec3d& direction, double t_min, double t_max, Visit&& visit) const {
    if (nodes_.empty()) return;
    // Classic front-to-back kd-tree traversal: at each split, the child on the origin's side comes first.
    struct Pending {
        std::uint32_t node;
        double t0, t1;
    };
    Pending stack[kMaxDepth + 2];
    int top = 0;
    stack[top++] = {0, t_min, t_max};
    while (top > 0) {
        const Pending p = stack[--top];
        const Node& node = nodes_[p.node];
        if (node.axis == 3) {
            if (node.child != kNoCell && !visit(node.child, p.t0, p.t1)) return;
            continue;
        }
        const int axis = int(node.axis);
        const double o = origin[axis], d = direction[axis];
        const std::uint32_t below = node.child, above = node.child + 1;
        if (d == 0) {  // parallel to the plane (on it: either closed child holds the line)
            stack[top++] = {o <= node.split ? below : above, p.t0, p.t1};
            continue;
        }
        // The child the line is in for t < t_split comes first; push it last.
        const double t_split = (node.split - o) / d;
        const std::uint32_t near = d > 0 ? below : above, far = d > 0 ? above : below;
        if (t_split >= p.t1) {
            stack[top++] = {near, p.t0, p.t1};
        } else if (t_split <= p.t0) {
            stack[top++] = {far, p.t0, p.t1};
        } else {
            stack[top++] = {far, t_split, p.t1};
            stack[top++] = {near, p.t0, t_split};
        }
    }
}

}  // namespace isotrace
