#pragma once
// The 26 directions from a cube's centre to its face centres, edge midpoints and corners, of unit length: probes
// around a point that see a surface in any direction up to the cube's resolution.
#include <array>

#include "renderer/math/vec3.h"

namespace isotrace {

inline const std::array<Vec3d, 26>& neighbour_directions() {
    static const std::array<Vec3d, 26> directions = [] {
        std::array<Vec3d, 26> all{};
        std::size_t n = 0;
        for (int x = -1; x <= 1; ++x)
            for (int y = -1; y <= 1; ++y)
                for (int z = -1; z <= 1; ++z)
                    if (x || y || z) all[n++] = normalize(Vec3d{double(x), double(y), double(z)});
        return all;
    }();
    return directions;
}

}  // namespace isotrace
