#include "geometry/polygonize/cube_cycles.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "renderer/math/vec3.h"

namespace isotrace {
namespace {

Vec3d corner_position(int c) { return {double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1)}; }

int corner_at(int axis, int along, int b_bit, int c_bit) {
    int coordinates[3];
    coordinates[axis] = along;
    coordinates[(axis + 1) % 3] = b_bit;
    coordinates[(axis + 2) % 3] = c_bit;
    return coordinates[0] | coordinates[1] << 1 | coordinates[2] << 2;
}

// The cube edge joining two corners that differ in one coordinate.
int edge_between(int a, int b) {
    const int differ = a ^ b;
    const int axis = differ == 1 ? 0 : (differ == 2 ? 1 : 2);
    const int low = std::min(a, b);
    const int b_bit = (low >> ((axis + 1) % 3)) & 1, c_bit = (low >> ((axis + 2) % 3)) & 1;
    return axis * 4 + b_bit + 2 * c_bit;
}

// The four corners of face (axis, side) in cyclic order, and the four edges between consecutive ones.
struct Face {
    std::array<int, 4> corners;
    std::array<int, 4> edges;  // edges[k] joins corners[k] and corners[k + 1]
};

Face face(int axis, int side) {
    Face f;
    const int bits[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k) f.corners[k] = corner_at(axis, side, bits[k][0], bits[k][1]);
    for (int k = 0; k < 4; ++k) f.edges[k] = edge_between(f.corners[k], f.corners[(k + 1) % 4]);
    return f;
}

bool edges_share_face(int e1, int e2) {
    const auto c1 = cube_edge_corners(e1), c2 = cube_edge_corners(e2);
    // Two distinct edges lie in one face when their four corners agree on some coordinate.
    for (int axis = 0; axis < 3; ++axis) {
        const int bit = (c1[0] >> axis) & 1;
        if (((c1[1] >> axis) & 1) == bit && ((c2[0] >> axis) & 1) == bit && ((c2[1] >> axis) & 1) == bit) return true;
    }
    return false;
}

CubeCycles trace(std::uint8_t inside) {
    const auto is_inside = [&](int c) { return (inside >> c) & 1; };
    const auto is_cut = [&](int e) {
        const auto c = cube_edge_corners(e);
        return is_inside(c[0]) != is_inside(c[1]);
    };
    // Each cut edge lies in two faces and gets one partner in each.
    std::array<std::array<int, 2>, 12> partners;
    std::array<int, 12> partner_count{};
    const auto pair = [&](int e1, int e2) {
        partners[e1][partner_count[e1]++] = e2;
        partners[e2][partner_count[e2]++] = e1;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const Face f = face(axis, side);
            std::vector<int> cut;
            for (int e : f.edges)
                if (is_cut(e)) cut.push_back(e);
            if (cut.size() == 2) {
                pair(cut[0], cut[1]);
            } else if (cut.size() == 4) {  // inside corners on a diagonal: cut each one off on its own
                for (int k = 0; k < 4; ++k)
                    if (is_inside(f.corners[k])) pair(f.edges[(k + 3) % 4], f.edges[k]);
            }
        }

    CubeCycles result;
    result.cycle_of_edge.fill(-1);
    for (int start = 0; start < 12; ++start) {
        if (!is_cut(start) || result.cycle_of_edge[start] >= 0) continue;
        CubeCycle& cycle = result.cycles[result.count];
        int previous = -1, current = start;
        do {
            result.cycle_of_edge[current] = std::int8_t(result.count);
            cycle.edges[cycle.length++] = std::int8_t(current);
            const int next = partners[current][0] != previous ? partners[current][0] : partners[current][1];
            previous = current;
            current = next;
        } while (current != start);
        // Orientation: the polygon's area vector (Newell, through the edge midpoints) must point from the inside
        // corners to the outside ones.
        Vec3d area, outward;
        for (int k = 0; k < cycle.length; ++k) {
            const auto c = cube_edge_corners(cycle.edges[k]);
            const auto n = cube_edge_corners(cycle.edges[(k + 1) % cycle.length]);
            const Vec3d p = (corner_position(c[0]) + corner_position(c[1])) * 0.5;
            const Vec3d q = (corner_position(n[0]) + corner_position(n[1])) * 0.5;
            area += cross(p, q);
            outward += is_inside(c[0]) ? corner_position(c[1]) - corner_position(c[0])
                                       : corner_position(c[0]) - corner_position(c[1]);
        }
        if (dot(area, outward) < 0) std::reverse(cycle.edges.begin(), cycle.edges.begin() + cycle.length);
        // A fan apex whose diagonals never join two edges of one face.
        cycle.needs_centre = true;
        for (int apex = 0; apex < cycle.length && cycle.needs_centre; ++apex) {
            bool clean = true;
            for (int k = 2; k + 1 < cycle.length; ++k)
                if (edges_share_face(cycle.edges[apex], cycle.edges[(apex + k) % cycle.length])) clean = false;
            if (clean) {
                cycle.needs_centre = false;
                cycle.apex = apex;
            }
        }
        ++result.count;
    }
    return result;
}

std::array<CubeCycles, 256> make_table() {
    std::array<CubeCycles, 256> table;
    for (int pattern = 0; pattern < 256; ++pattern) table[pattern] = trace(std::uint8_t(pattern));
    return table;
}

}  // namespace

std::array<int, 2> cube_edge_corners(int edge) {
    const int axis = edge / 4, b_bit = edge & 1, c_bit = (edge >> 1) & 1;
    return {corner_at(axis, 0, b_bit, c_bit), corner_at(axis, 1, b_bit, c_bit)};
}

const CubeCycles& cube_cycles(std::uint8_t inside_corners) {
    static const std::array<CubeCycles, 256> table = make_table();
    return table[inside_corners];
}

}  // namespace isotrace
