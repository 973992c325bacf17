#include "geometry/polygonize/collapse_topology.h"

#include <array>

#include "geometry/polygonize/cube_cycles.h"

namespace isotrace {
namespace {

class SignGrid {
public:
    explicit SignGrid(std::uint32_t inside) : inside_(inside) {}

    // Point with coordinate `along` on axis a and (u, v) on the next two axes (a + 1, a + 2) mod 3.
    bool at(int a, int along, int u, int v) const {
        int p[3];
        p[a] = along;
        p[(a + 1) % 3] = u;
        p[(a + 2) % 3] = v;
        return (inside_ >> (p[0] + 3 * p[1] + 9 * p[2])) & 1;
    }
    // The 8-corner pattern of the cube of side `size` at (x, y, z).
    std::uint8_t cube(int x, int y, int z, int size) const {
        std::uint8_t pattern = 0;
        for (int c = 0; c < 8; ++c)
            if (at(0, x + (c & 1) * size, y + ((c >> 1) & 1) * size, z + ((c >> 2) & 1) * size))
                pattern |= std::uint8_t(1 << c);
        return pattern;
    }

private:
    std::uint32_t inside_;
};

// Sign changes round a closed loop of points.
template <std::size_t N>
int changes(const std::array<bool, N>& loop) {
    int count = 0;
    for (std::size_t k = 0; k < N; ++k) count += loop[k] != loop[(k + 1) % N];
    return count;
}

int child_index(int x, int y, int z) { return x + 2 * y + 4 * z; }

}  // namespace

bool collapse_keeps_topology(std::uint32_t inside) {
    const SignGrid grid(inside);
    int surface_children = 0;
    std::array<int, 8> component{};
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) {
                const std::uint8_t pattern = grid.cube(x, y, z, 1);
                if (cube_cycles(pattern).count > 1) return false;
                const bool has_surface = pattern != 0 && pattern != 255;
                surface_children += has_surface;
                component[std::size_t(child_index(x, y, z))] = has_surface ? child_index(x, y, z) : -1;
            }
    if (surface_children == 0 || cube_cycles(grid.cube(0, 0, 0, 2)).count != 1) return false;

    int cut_edges = 0, cut_faces = 0;
    const auto root = [&](int c) {
        while (component[std::size_t(c)] != c) c = component[std::size_t(c)];
        return c;
    };
    for (int a = 0; a < 3; ++a) {
        for (int u = 0; u < 3; ++u)
            for (int v = 0; v < 3; ++v) {
                const bool s0 = grid.at(a, 0, u, v), s1 = grid.at(a, 1, u, v), s2 = grid.at(a, 2, u, v);
                cut_edges += (s0 != s1) + (s1 != s2);
                const bool node_edge = (u != 1) && (v != 1);
                if (node_edge && (s0 != s1) + (s1 != s2) > 1) return false;
            }
        for (int plane = 0; plane < 3; ++plane) {
            for (int u = 0; u < 2; ++u)
                for (int v = 0; v < 2; ++v) {
                    const std::array<bool, 4> loop = {grid.at(a, plane, u, v), grid.at(a, plane, u + 1, v),
                                                      grid.at(a, plane, u + 1, v + 1), grid.at(a, plane, u, v + 1)};
                    const int c = changes(loop);
                    if (c > 2) return false;
                    if (c == 0) continue;
                    ++cut_faces;
                    if (plane != 1) continue;
                    // An inner face with an arc joins the children on either side of it.
                    int below[3], above[3];
                    below[a] = 0;
                    above[a] = 1;
                    below[(a + 1) % 3] = above[(a + 1) % 3] = u;
                    below[(a + 2) % 3] = above[(a + 2) % 3] = v;
                    component[std::size_t(root(child_index(below[0], below[1], below[2])))] =
                        root(child_index(above[0], above[1], above[2]));
                }
            if (plane == 1) continue;
            const std::array<bool, 8> boundary = {grid.at(a, plane, 0, 0), grid.at(a, plane, 1, 0), grid.at(a, plane, 2, 0),
                                                  grid.at(a, plane, 2, 1), grid.at(a, plane, 2, 2), grid.at(a, plane, 1, 2),
                                                  grid.at(a, plane, 0, 2), grid.at(a, plane, 0, 1)};
            const int c = changes(boundary);
            if (c > 2 || (c == 0 && grid.at(a, plane, 1, 1) != boundary[0])) return false;
        }
    }
    int components = 0;
    for (int c = 0; c < 8; ++c) components += component[std::size_t(c)] >= 0 && root(c) == c;
    return components == 1 && cut_edges - cut_faces + surface_children == 1;
}

}  // namespace isotrace
