#pragma once
// A compact bounding-volume hierarchy over the support boxes of a blob group's elements, for the group's two
// neighbourhood questions: which elements may the stretch [a, b] of a ray meet, and which contain a point.
// It replaces explicit neighbour lists (tens of indices per element in dense clouds) with about 20 bytes per
// element: float boxes rounded outwards, up to four elements per leaf, and the element order.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/implicit/metacube.h"

namespace isotrace {

class ElementBvh {
public:
    void build(std::span<const WorldBounds> boxes);
    std::size_t memory_bytes() const;

    // Calls visit(element) for every element whose box the segment o + t·d, t in [a, b], may meet (a
    // conservative test: some elements whose box it misses are visited too).
    template <class Visit>
    void for_each_near_segment(const Vec3d& origin, const Vec3d& direction, double a, double b, Visit&& visit) const;
    // Calls visit(element) for every element whose box contains p.
    template <class Visit>
    void for_each_containing(const Vec3d& p, Visit&& visit) const;

private:
    // A leaf holds order_[first, first + count); an inner node (count = 0) has children at index + 1 and `first`.
    struct Node {
        float lower[3], upper[3];
        std::uint32_t first = 0, count = 0;
    };
    std::uint32_t build_node(std::span<const WorldBounds> boxes, std::vector<Vec3d>& centres, std::uint32_t begin,
                             std::uint32_t end);
    static bool segment_meets(const Node& node, const Vec3d& origin, const Vec3d& inverse_direction, double a,
                              double b);

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;
};

// Slab test. An axis the segment does not move along gives (bound − o)·∞: ±∞ when o is off the bound (a clean
// accept or reject) and NaN when o lies exactly on it. The boxes are rounded outwards, so such a segment cannot
// enter the support itself, and whichever answer the NaN comparisons give is safe.
inline bool ElementBvh::segment_meets(const Node& node, const Vec3d& origin, const Vec3d& inverse_direction,
                                      double a, double b) {
    double near = a, far = b;
    for (int k = 0; k < 3; ++k) {
        const double t0 = (double(node.lower[k]) - origin[k]) * inverse_direction[k];
        const double t1 = (double(node.upper[k]) - origin[k]) * inverse_direction[k];
        const double entry = t0 < t1 ? t0 : t1, exit = t0 < t1 ? t1 : t0;
        if (entry > near) near = entry;
        if (exit < far) far = exit;
    }
    return near <= far;
}

template <class Visit>
void ElementBvh::for_each_near_segment(const Vec3d& origin, const Vec3d& direction, double a, double b,
                                       Visit&& visit) const {
    if (nodes_.empty()) return;
    const Vec3d inverse(1 / direction.x, 1 / direction.y, 1 / direction.z);
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!segment_meets(node, origin, inverse, a, b)) continue;
        if (node.count > 0) {
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) visit(order_[k]);
        } else {
            stack[top++] = node.first;
            stack[top++] = std::uint32_t(&node - nodes_.data()) + 1;
        }
    }
}

template <class Visit>
void ElementBvh::for_each_containing(const Vec3d& p, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        bool inside = true;
        for (int k = 0; k < 3; ++k) inside = inside && p[k] >= node.lower[k] && p[k] <= node.upper[k];
        if (!inside) continue;
        if (node.count > 0) {
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) visit(order_[k]);
        } else {
            stack[top++] = node.first;
            stack[top++] = std::uint32_t(&node - nodes_.data()) + 1;
        }
    }
}

}  // namespace isotrace
