#pragma once
// The marching-cubes table, generated at start-up rather than typed in: for each of the 256 sign patterns of a
// cube's corners, the surface's polygons as cycles of cut cube edges.
//
// Conventions shared by every polygoniser here. Corner c sits at (c & 1, (c >> 1) & 1, (c >> 2) & 1). Edge e runs
// along axis a = e / 4 from the corner with coordinate 0 on a to the one with 1; its position on the other two
// axes b = (a + 1) % 3 and c = (a + 2) % 3 is (e & 1, (e >> 1) & 1).
//
// Polygons are traced on the cube's faces: each face's cut edges are paired by segments, and a face with four
// cut edges (inside corners on one diagonal) pairs the two edges around each inside corner ("inside corners
// stay apart"). The rule reads only the face's own four signs, so two cells sharing a face draw the same
// segments there: the surface is crack-free and closed, and each cycle (a disc) is one connected component of
// the surface in the cell — the unit manifold dual contouring gives one vertex.
#include <array>
#include <cstdint>

namespace isotrace {

struct CubeCycle {
    std::array<std::int8_t, 12> edges{};  // counter-clockwise seen from outside (the normal points outwards)
    int length = 0;
    // Triangulate around an added centre vertex instead of as a fan from edges[apex]: set when every fan would
    // draw a diagonal between two edges of one face, which the neighbour across that face might draw as well.
    bool needs_centre = false;
    int apex = 0;
};

struct CubeCycles {
    std::array<CubeCycle, 4> cycles{};
    int count = 0;
    std::array<std::int8_t, 12> cycle_of_edge{};  // −1 for an edge the surface does not cut
};

// Bit c of `inside_corners` set: corner c is inside (field < 0).
const CubeCycles& cube_cycles(std::uint8_t inside_corners);

// The two corners of cube edge e (coordinate 0 then 1 along its axis).
std::array<int, 2> cube_edge_corners(int edge);

}  // namespace isotrace
