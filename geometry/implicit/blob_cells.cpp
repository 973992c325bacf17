#include "geometry/implicit/blob_cells.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "renderer/core/parallel_for.h"

namespace isotrace {
namespace {

// A cell stops splitting when it lists at most this many elements...
constexpr std::size_t kLeafElements = 16;
// ...or when its longest side is at most this many mean support radii of its elements: smaller cells would list
// nearly the same elements again (supports overlap), costing memory for little less work per ray. 1.5 rather than
// 2: a shadow ray's march starts among the elements that made the surface, and a smaller cell holds fewer of them
// (1 radius costs more memory and is slower: docs/decisions.md, "Blob groups: cells as Embree primitives").
constexpr double kSmallestCellInRadii = 1.5;

// Does the element's support reach into the closed box? Exact for metaballs (distance from the centre to the box
// ≤ R); the support's bounding box for metacubes (a few extra elements in corner cells, never a missing one).
bool support_meets(const Metacube& element, const WorldBounds& box) {
    const WorldBounds support = element.support_bounds();
    for (int k = 0; k < 3; ++k)
        if (support.lower[k] > box.upper[k] || support.upper[k] < box.lower[k]) return false;
    if (!element.is_metaball()) return true;
    return element.nearest_squared_distance(box) <= element.radius() * element.radius();
}

}  // namespace

void BlobCells::build(std::span<const Metacube> elements) {
    nodes_.clear();
    cells_.clear();
    element_ids_.clear();
    if (elements.empty()) return;
    WorldBounds root = elements[0].support_bounds();
    for (const Metacube& element : elements) {
        const WorldBounds b = element.support_bounds();
        root = {min(root.lower, b.lower), max(root.upper, b.upper)};
    }
    std::vector<std::uint32_t> all(elements.size());
    std::iota(all.begin(), all.end(), 0u);
    nodes_.emplace_back();
    root_ = root;
    build_node(elements, 0, root, all, 0);
    nodes_.shrink_to_fit();
    cells_.shrink_to_fit();
    element_ids_.shrink_to_fit();
    surface_cells_ = std::uint32_t(cells_.size());
}

void BlobCells::restrict_to_surface(const SurfaceRegion& region) {
    std::vector<std::optional<WorldBounds>> regions(cells_.size());
    parallel_for(std::size_t(0), cells_.size(), [&](std::size_t c) {
        regions[c] = region({cells_[c].lower, cells_[c].upper}, elements_of(cells_[c]));
    });
    // New order: the cells with a region first, each group in its old order (deterministic).
    std::vector<std::uint32_t> new_index(cells_.size());
    std::vector<Cell> reordered;
    reordered.reserve(cells_.size());
    for (int with_region = 1; with_region >= 0; --with_region)
        for (std::size_t c = 0; c < cells_.size(); ++c) {
            if (regions[c].has_value() != bool(with_region)) continue;
            new_index[c] = std::uint32_t(reordered.size());
            Cell cell = cells_[c];
            cell.lower = with_region ? regions[c]->lower : Vec3d(INFINITY, INFINITY, INFINITY);
            cell.upper = with_region ? regions[c]->upper : Vec3d(-INFINITY, -INFINITY, -INFINITY);
            reordered.push_back(cell);
        }
    surface_cells_ = std::uint32_t(std::count_if(regions.begin(), regions.end(), [](const auto& r) { return r; }));
    for (Node& node : nodes_)
        if (node.axis == 3 && node.child != kNoCell) node.child = new_index[node.child];
    cells_ = std::move(reordered);
}

void BlobCells::build_node(std::span<const Metacube> elements, std::uint32_t node, const WorldBounds& box,
                           const std::vector<std::uint32_t>& ids, int depth) {
    const Vec3d extent = box.upper - box.lower;
    const int axis = longest_axis(extent);
    double mean_reach = 0;
    for (std::uint32_t id : ids) mean_reach += elements[id].support_radius();
    mean_reach /= double(std::max<std::size_t>(ids.size(), 1));

    std::vector<std::uint32_t> below, above;
    WorldBounds below_box = box, above_box = box;
    const double split = 0.5 * (box.lower[axis] + box.upper[axis]);
    const bool may_split = ids.size() > kLeafElements && extent[axis] > kSmallestCellInRadii * mean_reach &&
                           depth < kMaxDepth && split > box.lower[axis] && split < box.upper[axis];
    if (may_split) {
        below_box.upper[axis] = above_box.lower[axis] = split;
        for (std::uint32_t id : ids) {
            if (support_meets(elements[id], below_box)) below.push_back(id);
            if (support_meets(elements[id], above_box)) above.push_back(id);
        }
    }
    // Coincident or nested supports: when no element is left behind by either side, splitting only duplicates.
    if (!may_split || (below.size() == ids.size() && above.size() == ids.size())) {
        if (ids.empty()) return;  // the node stays an empty leaf
        Cell cell;
        cell.lower = box.upper;
        cell.upper = box.lower;
        for (std::uint32_t id : ids) {
            const WorldBounds support = elements[id].support_bounds();
            cell.lower = min(cell.lower, support.lower);
            cell.upper = max(cell.upper, support.upper);
        }
        cell.lower = max(cell.lower, box.lower);  // shrunk to what its elements reach, inside its kd cell
        cell.upper = min(cell.upper, box.upper);
        cell.first = std::uint32_t(element_ids_.size());
        cell.count = std::uint32_t(ids.size());
        element_ids_.insert(element_ids_.end(), ids.begin(), ids.end());
        nodes_[node].child = std::uint32_t(cells_.size());
        cells_.push_back(cell);
        return;
    }
    const std::uint32_t child = std::uint32_t(nodes_.size());
    nodes_[node].axis = std::uint32_t(axis);
    nodes_[node].split = split;
    nodes_[node].child = child;
    nodes_.emplace_back();
    nodes_.emplace_back();
    build_node(elements, child, below_box, below, depth + 1);
    build_node(elements, child + 1, above_box, above, depth + 1);
}

std::size_t BlobCells::memory_bytes() const {
    return nodes_.capacity() * sizeof(Node) + cells_.capacity() * sizeof(Cell) +
           element_ids_.capacity() * sizeof(std::uint32_t);
}

std::span<const std::uint32_t> BlobCells::elements_near(const Vec3d& p) const {
    if (nodes_.empty()) return {};
    // A point a hair outside the supports' bounds still gets the cell at their edge: a lone hard cube's faces are
    // those bounds, and a point computed on a face rounds to either side of it. Its elements add nothing there (no
    // support reaches out), but a hard cube's normal is taken from the cube's nearest face, which must be listed.
    for (int k = 0; k < 3; ++k) {
        const double pad =
            1e-9 * (root_.upper[k] - root_.lower[k] + std::abs(root_.lower[k]) + std::abs(root_.upper[k]));
        if (p[k] < root_.lower[k] - pad || p[k] > root_.upper[k] + pad) return {};
    }
    std::uint32_t index = 0;
    while (nodes_[index].axis != 3) {
        const Node& node = nodes_[index];
        index = node.child + (p[int(node.axis)] <= node.split ? 0 : 1);
    }
    const std::uint32_t cell = nodes_[index].child;
    if (cell == kNoCell) return {};
    return elements_of(cell);
}

}  // namespace isotrace
