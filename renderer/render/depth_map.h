#pragma once
// The view depth of the first hit through the centre of every pixel: one exact value per pixel (no filter, no
// averaging across a silhouette), the data of a range image. Primary rays only, without integrator, sampler or
// shading, so `isotrace bench` times exactly Embree and the shapes with it.
#include <limits>
#include <vector>

#include "renderer/scene/loaded_scene.h"

namespace isotrace {

struct DepthMap {
    PixelBounds window;       // the film's crop window, in full-raster pixels
    std::vector<float> depth;  // row-major over the window; +inf where the ray hit nothing

    static constexpr float kNoHit = std::numeric_limits<float>::infinity();
    std::size_t index(int x, int y) const {
        return std::size_t(y - window.y0) * std::size_t(window.width()) + std::size_t(x - window.x0);
    }
    float at(int x, int y) const { return depth[index(x, y)]; }
};

// The ray through the centre of pixel (x, y), full-raster coordinates (thin-lens cameras: from the lens centre).
Ray pixel_centre_ray(const LoadedScene& scene, int x, int y);

// Distance along the camera's viewing axis (Camera::view_depth, the same quantity as the depth AOV), world units,
// for every pixel of scene.film.crop; rows run in parallel. Thin-lens cameras use the lens centre.
DepthMap render_depth_map(const LoadedScene& scene);

}  // namespace isotrace
