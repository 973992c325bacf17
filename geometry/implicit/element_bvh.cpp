#include "geometry/implicit/element_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace isotrace {
namespace {

constexpr std::uint32_t kLeafSize = 4;

float round_down(double x) { return std::nextafter(float(x), -std::numeric_limits<float>::infinity()); }
float round_up(double x) { return std::nextafter(float(x), std::numeric_limits<float>::infinity()); }

}  // namespace

void ElementBvh::build(std::span<const WorldBounds> boxes) {
    nodes_.clear();
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0u);
    if (boxes.empty()) return;
    std::vector<Vec3d> centres(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) centres[i] = (boxes[i].lower + boxes[i].upper) * 0.5;
    nodes_.reserve(2 * (boxes.size() / kLeafSize + 1));
    build_node(boxes, centres, 0, std::uint32_t(boxes.size()));
    nodes_.shrink_to_fit();
}

// Median split along the widest axis of the centres: balanced, so the depth stays below the traversal stack's 64.
std::uint32_t ElementBvh::build_node(std::span<const WorldBounds> boxes, std::vector<Vec3d>& centres,
                                     std::uint32_t begin, std::uint32_t end) {
    const std::uint32_t index = std::uint32_t(nodes_.size());
    nodes_.emplace_back();
    Vec3d lower = boxes[order_[begin]].lower, upper = boxes[order_[begin]].upper;
    Vec3d centre_lower = centres[order_[begin]], centre_upper = centre_lower;
    for (std::uint32_t k = begin; k < end; ++k) {
        lower = min(lower, boxes[order_[k]].lower);
        upper = max(upper, boxes[order_[k]].upper);
        centre_lower = min(centre_lower, centres[order_[k]]);
        centre_upper = max(centre_upper, centres[order_[k]]);
    }
    for (int k = 0; k < 3; ++k) {
        nodes_[index].lower[k] = round_down(lower[k]);
        nodes_[index].upper[k] = round_up(upper[k]);
    }
    if (end - begin <= kLeafSize) {
        nodes_[index].first = begin;
        nodes_[index].count = end - begin;
        return index;
    }
    const Vec3d extent = centre_upper - centre_lower;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](std::uint32_t i, std::uint32_t j) { return centres[i][axis] < centres[j][axis]; });
    build_node(boxes, centres, begin, middle);  // the left child follows its parent
    const std::uint32_t right = build_node(boxes, centres, middle, end);
    nodes_[index].first = right;
    nodes_[index].count = 0;
    return index;
}

std::size_t ElementBvh::memory_bytes() const {
    return nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(std::uint32_t);
}

}  // namespace isotrace
