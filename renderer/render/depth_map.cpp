#include "renderer/render/depth_map.h"

#include "renderer/core/parallel_for.h"
#include "renderer/embree/embree_device.h"

namespace isotrace {

Ray pixel_centre_ray(const LoadedScene& scene, int x, int y) {
    return scene.camera->generate_ray(float(x) + 0.5f, float(y) + 0.5f, {0.5f, 0.5f});
}

DepthMap render_depth_map(const LoadedScene& scene) {
    DepthMap map;
    map.window = scene.film.crop;
    map.depth.assign(std::size_t(map.window.area()), DepthMap::kNoHit);
    parallel_for(map.window.y0, map.window.y1, [&](int y) {
        enable_flush_to_zero();  // as in every render thread: this worker may not have rendered before
        for (int x = map.window.x0; x < map.window.x1; ++x) {
            const Ray ray = pixel_centre_ray(scene, x, y);
            if (const std::optional<SurfaceHit> hit = scene.scene->intersect(ray, RayKind::Camera))
                map.depth[map.index(x, y)] = scene.camera->view_depth(hit->position);
        }
    });
    return map;
}

}  // namespace isotrace
