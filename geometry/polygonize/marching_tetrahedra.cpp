#include "geometry/polygonize/marching_tetrahedra.h"

#include <utility>

namespace isotrace {
namespace {

struct IntPoint {
    int x, y, z;
};

IntPoint corner_position(int corner) { return {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1}; }

// Twice the midpoint of an edge, in integers, so that the orientation test below is exact.
IntPoint doubled_midpoint(const CutEdge& edge) {
    const IntPoint a = corner_position(edge.inside_corner), b = corner_position(edge.outside_corner);
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}

// Puts the triangle in counter-clockwise order seen from outside. The triangle through the cut edges'
// midpoints separates the tetrahedron's inside corners from its outside ones, so the sign of its normal along
// any inside→outside edge decides the order exactly (the midpoint triangle is never degenerate).
CutTriangle oriented(CutTriangle triangle) {
    const IntPoint p0 = doubled_midpoint(triangle[0]), p1 = doubled_midpoint(triangle[1]),
                   p2 = doubled_midpoint(triangle[2]);
    const int ux = p1.x - p0.x, uy = p1.y - p0.y, uz = p1.z - p0.z;
    const int vx = p2.x - p0.x, vy = p2.y - p0.y, vz = p2.z - p0.z;
    const int nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const IntPoint in = corner_position(triangle[0].inside_corner), out = corner_position(triangle[0].outside_corner);
    if (nx * (out.x - in.x) + ny * (out.y - in.y) + nz * (out.z - in.z) < 0) std::swap(triangle[1], triangle[2]);
    return triangle;
}

}  // namespace

const std::array<std::array<int, 4>, 6>& kuhn_tetrahedra() {
    // One tetrahedron per order in which the path 0 → 7 raises the three axes.
    static const std::array<std::array<int, 4>, 6> table = {{
        {0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7},
    }};
    return table;
}

int cut_tetrahedron(const std::array<int, 4>& tetrahedron, std::uint8_t inside_corners,
                    std::array<CutTriangle, 2>& triangles) {
    std::array<int, 4> inside{}, outside{};
    int inside_count = 0, outside_count = 0;
    for (int corner : tetrahedron) {
        if ((inside_corners >> corner) & 1)
            inside[std::size_t(inside_count++)] = corner;
        else
            outside[std::size_t(outside_count++)] = corner;
    }
    if (inside_count == 1) {
        triangles[0] = oriented({CutEdge{inside[0], outside[0]}, CutEdge{inside[0], outside[1]},
                                 CutEdge{inside[0], outside[2]}});
        return 1;
    }
    if (inside_count == 3) {
        triangles[0] = oriented({CutEdge{inside[0], outside[0]}, CutEdge{inside[1], outside[0]},
                                 CutEdge{inside[2], outside[0]}});
        return 1;
    }
    if (inside_count == 2) {
        // The cut is a quad whose corners, in cyclic order, lie on edges i0-o0, i0-o1, i1-o1, i1-o0.
        const CutEdge e00{inside[0], outside[0]}, e01{inside[0], outside[1]};
        const CutEdge e11{inside[1], outside[1]}, e10{inside[1], outside[0]};
        triangles[0] = oriented({e00, e01, e11});
        triangles[1] = oriented({e00, e11, e10});
        return 2;
    }
    return 0;
}

}  // namespace isotrace
