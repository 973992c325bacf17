#include "geometry/polygonize/octree_simplification.h"

#include <algorithm>
#include <numeric>
#include <optional>

#include "geometry/polygonize/collapse_topology.h"
#include "renderer/core/parallel_for.h"

namespace isotrace {
namespace {

constexpr std::uint32_t kNone = ~std::uint32_t(0);

// A leaf holding surface: a finest cell with one cycle, or a collapsed node.
struct Leaf {
    LatticeKey key;
    Qef qef;
    Vec3d vertex;
};

LatticeKey ancestor(LatticeKey cell, int shift) {
    const LatticeIndex i = lattice_index(cell);
    return lattice_key({i[0] >> shift, i[1] >> shift, i[2] >> shift});
}

const Leaf* find_leaf(const std::vector<Leaf>& leaves, LatticeKey key) {
    const auto at = std::lower_bound(leaves.begin(), leaves.end(), key, [](const Leaf& l, LatticeKey k) { return l.key < k; });
    return at != leaves.end() && at->key == key ? &*at : nullptr;
}

// The signs at the 27 corners of a node's children (collapse_topology.h), from the samples where the lattice
// was sampled and from the field elsewhere (corners of empty space the descent did not enter).
std::uint32_t child_corner_signs(const LatticeSamples& samples, const CartesianLattice& lattice,
                                 const ImplicitField& field, int level, const LatticeIndex& node) {
    const int child = 1 << (lattice.depth() - level - 1);
    std::uint32_t inside = 0;
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) {
                const LatticeIndex corner = {(2 * node[0] + x) * child, (2 * node[1] + y) * child, (2 * node[2] + z) * child};
                const auto sampled = samples.corner(lattice_key(corner));
                const bool is_inside = sampled ? samples.corner_inside[*sampled] != 0
                                               : field.value(lattice.position(Vec3d(corner[0], corner[1], corner[2]))) < 0;
                if (is_inside) inside |= 1u << (x + 3 * y + 9 * z);
            }
    return inside;
}

struct Group {
    LatticeKey parent;
    std::size_t begin, end;  // a range of the cells ordered by parent
};

}  // namespace

SimplificationStatistics simplify_octree(const LatticeSamples& samples, const CartesianLattice& lattice,
                                         const ImplicitField& field, double tolerance, DualVertices& vertices) {
    SimplificationStatistics statistics;
    const int depth = lattice.depth();
    statistics.coarsest_level = depth;
    const std::size_t cells = samples.cells.size();
    const double limit = tolerance * tolerance;

    // Level L: the cells with one cycle are leaves that may collapse; a cell with several blocks its ancestors.
    std::vector<int> leaf_level(cells, depth);
    std::vector<std::uint8_t> open(cells);
    std::vector<Leaf> leaves;
    for (std::size_t i = 0; i < cells; ++i)
        if (cube_cycles(samples.inside[i]).count == 1) {
            open[i] = 1;
            leaves.push_back({samples.cells[i], {}, vertices.positions[vertices.vertex(i, 0)]});
        }
    {
        std::vector<std::size_t> leaf_cell;
        for (std::size_t i = 0; i < cells; ++i)
            if (open[i]) leaf_cell.push_back(i);
        parallel_for(std::size_t(0), leaves.size(), [&](std::size_t k) {
            const std::size_t i = leaf_cell[k];
            leaves[k].qef = cycle_qef(samples, lattice, lattice_index(samples.cells[i]), cube_cycles(samples.inside[i]).cycles[0]);
        });
    }

    std::vector<std::vector<Leaf>> collapsed(static_cast<std::size_t>(depth));  // per level above L: its collapsed nodes, by key
    std::vector<std::size_t> order(cells);
    std::vector<LatticeKey> parent_of(cells);
    for (int level = depth - 1; level >= 0 && !leaves.empty(); --level) {
        const int shift = depth - level;
        for (std::size_t i = 0; i < cells; ++i) parent_of[i] = ancestor(samples.cells[i], shift);
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return parent_of[a] < parent_of[b]; });
        // Nodes whose surface cells all lie in leaves one level down.
        std::vector<Group> groups;
        for (std::size_t b = 0; b < cells;) {
            std::size_t e = b;
            bool all_open = true;
            for (; e < cells && parent_of[order[e]] == parent_of[order[b]]; ++e) all_open = all_open && open[order[e]];
            if (all_open) groups.push_back({parent_of[order[b]], b, e});
            b = e;
        }
        std::vector<std::optional<Leaf>> made(groups.size());
        std::vector<std::uint8_t> refused_by_error(groups.size());
        parallel_for(std::size_t(0), groups.size(), [&](std::size_t g) {
            const Group& group = groups[g];
            const LatticeIndex node = lattice_index(group.parent);
            if (!collapse_keeps_topology(child_corner_signs(samples, lattice, field, level, node))) return;
            Leaf leaf{group.parent, {}, {}};
            // Every surface cell of the node lies in a leaf one level down; children without a leaf are empty.
            for (int c = 0; c < 8; ++c)
                if (const Leaf* child = find_leaf(leaves, lattice_key({2 * node[0] + (c & 1), 2 * node[1] + ((c >> 1) & 1),
                                                                       2 * node[2] + ((c >> 2) & 1)})))
                    leaf.qef.merge(child->qef);
            leaf.vertex = lattice.clamp_to_node(leaf.qef.solve(), level, node);
            if (!(leaf.qef.error(leaf.vertex) <= limit)) {
                refused_by_error[g] = 1;
                return;
            }
            made[g] = leaf;
        });

        std::vector<std::uint8_t> still_open(cells);
        std::vector<Leaf> next;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            if (!made[g]) {
                (refused_by_error[g] ? statistics.rejected_by_error : statistics.rejected_by_topology) += 1;
                continue;
            }
            next.push_back(*made[g]);
            for (std::size_t k = groups[g].begin; k < groups[g].end; ++k) {
                still_open[order[k]] = 1;
                leaf_level[order[k]] = level;
            }
        }
        statistics.collapsed_nodes += next.size();
        if (!next.empty()) statistics.coarsest_level = level;
        open.swap(still_open);
        leaves.swap(next);
        collapsed[std::size_t(level)] = leaves;
    }

    // Number the vertices in cell order: a cell below L keeps its cycles' vertices, a collapsed leaf gets one.
    DualVertices result;
    result.first_cycle = vertices.first_cycle;
    result.vertex_of_cycle.resize(vertices.vertex_of_cycle.size());
    result.clamped = vertices.clamped;
    std::vector<std::vector<std::uint32_t>> numbered(collapsed.size());
    for (std::size_t l = 0; l < collapsed.size(); ++l) numbered[l].assign(collapsed[l].size(), kNone);
    for (std::size_t i = 0; i < cells; ++i) {
        const std::uint32_t first = vertices.first_cycle[i];
        if (leaf_level[i] == depth) {
            for (std::uint32_t c = first; c < vertices.first_cycle[i + 1]; ++c) {
                result.vertex_of_cycle[c] = std::uint32_t(result.positions.size());
                result.positions.push_back(vertices.positions[vertices.vertex_of_cycle[c]]);
            }
            continue;
        }
        const auto level = std::size_t(leaf_level[i]);
        const Leaf* leaf = find_leaf(collapsed[level], ancestor(samples.cells[i], depth - int(level)));
        std::uint32_t& number = numbered[level][std::size_t(leaf - collapsed[level].data())];
        if (number == kNone) {
            number = std::uint32_t(result.positions.size());
            result.positions.push_back(leaf->vertex);
        }
        result.vertex_of_cycle[first] = number;
    }
    vertices = std::move(result);
    return statistics;
}

}  // namespace isotrace
