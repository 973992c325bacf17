#pragma once
// Range images after T.-E. Kim et al., "3D Shape Reconstruction based on Superquadrics and Single Z-buffer CSG
// Rendering": depth mapped to 256 grey levels, g = (Z − Zmin)·256 / (Zmax − Zmin), clamped to 0..255.
//
// The paper's Z grows towards the viewer (its z-buffer keeps the larger Z as "closer to the observer"), so
// near is bright. We measure the view depth d (distance along the viewing axis, growing away from the camera),
// so Z = −d and
//     g = (d_far − d)·256 / (d_far − d_near):
// the near depth maps to 255 (white), the far depth to 0 (black). Pixels that hit nothing are 0, like the far
// plane: the background is black. `near_is_bright = false` reads Z as the depth itself instead,
// g = (d − d_near)·256 / (d_far − d_near): near black, far and background white.
#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/render/depth_map.h"

namespace isotrace {

struct DepthRange {
    float near = 0, far = 1;     // view depths mapped to the brightest and darkest grey (swapped when !near_is_bright)
    bool near_is_bright = true;  // the paper's convention
};

// The smallest and largest depth over the pixels that hit something; std::nullopt if none did.
std::optional<DepthRange> depth_range_of_hits(const DepthMap& map);

// Grey level of one depth; no hit (+inf) is as far as far (0, or 255 when near is dark). A range with
// far == near maps every hit to the near level.
std::uint8_t range_grey_level(float depth, const DepthRange& range);

// The whole map as 8-bit grey, row-major over map.window.
std::vector<std::uint8_t> range_image(const DepthMap& map, const DepthRange& range);

}  // namespace isotrace
