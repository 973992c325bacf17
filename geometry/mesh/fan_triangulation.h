#pragma once
// Both loaders split polygons the same way, so a quad gives the same triangles whichever format it came in.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace isotrace {

// Appends the fan (v0, v[i], v[i+1]) of a convex polygon, keeping its winding. Polygons with fewer than
// three corners add nothing: they enclose no area.
inline void append_fan_triangles(std::span<const std::uint32_t> polygon,
                                 std::vector<std::array<std::uint32_t, 3>>& triangles) {
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
        triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
    }
}

}  // namespace isotrace
