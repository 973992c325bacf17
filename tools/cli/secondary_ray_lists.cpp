#include "tools/cli/secondary_ray_lists.h"

#include <cmath>
#include <limits>
#include <optional>

#include "geometry/csg/transformed_bounds.h"
#include "renderer/core/input_error.h"
#include "renderer/core/parallel_for.h"
#include "renderer/embree/embree_device.h"
#include "renderer/plugin/shadow_ray.h"
#include "renderer/render/depth_map.h"
#include "renderer/sampling/independent_sampler.h"
#include "renderer/sampling/warps.h"

namespace isotrace::cli {
namespace {

Vec3f light_above(const Bounds3f& bounds, const std::string& scene) {
    if (bounds.empty() || !std::isfinite(bounds.lower.x + bounds.lower.y + bounds.lower.z + bounds.upper.x +
                                         bounds.upper.y + bounds.upper.z))
        throw InputError({}, scene, "the scene has no finite bounds to place the benchmark's light above");
    const float height = bounds.upper.y - bounds.lower.y;
    return {0.5f * (bounds.lower.x + bounds.upper.x), bounds.upper.y + (height > 0 ? height : 1.0f),
            0.5f * (bounds.lower.z + bounds.upper.z)};
}

// The world bounds of the objects' own shapes. Not Embree's scene bounds: those follow the acceleration structure (a
// blob group's cell boxes shrink to where its surface may lie), so the light, and with it every shadow ray, would
// move whenever that changes, and two builds would not time the same rays.
Bounds3f content_bounds(const RenderScene& scene) {
    Bounds3f bounds;
    for (std::uint32_t id = 0; id < scene.object_count(); ++id) {
        const SceneObject object = scene.object(id);
        Bounds3f own = object.shape->bounds();
        if (own.empty()) continue;
        if (object.instanced) own = transformed_bounds(Vec3d(own.lower), Vec3d(own.upper), object.to_world);
        bounds.extend(own.lower);
        bounds.extend(own.upper);
    }
    return bounds;
}

struct RowRays {
    std::size_t hits = 0;
    std::vector<Ray> shadow, bounce;
};

}  // namespace

SecondaryRayLists build_secondary_rays(const LoadedScene& scene, float clearance) {
    SecondaryRayLists lists;
    lists.light = light_above(content_bounds(*scene.scene), scene.path);
    const PixelBounds window = scene.film.crop;
    const IndependentSampler sampler(scene.seed);
    std::vector<RowRays> rows(std::size_t(window.height()));
    parallel_for(window.y0, window.y1, [&](int y) {
        enable_flush_to_zero();  // as in every render thread
        RowRays& row = rows[std::size_t(y - window.y0)];
        for (int x = window.x0; x < window.x1; ++x) {
            const Ray camera_ray = pixel_centre_ray(scene, x, y);
            std::optional<SurfaceHit> found = scene.scene->intersect(camera_ray, RayKind::Camera);
            if (!found) continue;
            SurfaceHit& hit = *found;
            ++row.hits;
            if (dot(hit.geometric_normal, camera_ray.direction) > 0) {  // two-sided: face the camera
                hit.geometric_normal = -hit.geometric_normal;
                hit.shading_normal = -hit.shading_normal;
            }
            hit.position_error += clearance;  // spawn_origin pushes off by it
            const Vec3f to_light = lists.light - hit.position;
            const float distance = length(to_light);
            if (distance > 0 && dot(to_light, hit.geometric_normal) > 0)
                row.shadow.push_back(shadow_ray(hit, to_light / distance, distance, LightPoint::OnASurface));
            const PixelSampleKey key{std::uint32_t(x), std::uint32_t(y), 0};
            const Vec3f local = square_to_cosine_hemisphere({sampler.sample(key, 0), sampler.sample(key, 1)});
            Vec3f tangent, bitangent;
            orthonormal_basis(hit.shading_normal, tangent, bitangent);
            const Vec3f direction = tangent * local.x + bitangent * local.y + hit.shading_normal * local.z;
            if (dot(direction, hit.geometric_normal) > 0)
                row.bounce.push_back(
                    {hit.spawn_origin(direction), direction, 0, std::numeric_limits<float>::infinity()});
        }
    });
    for (RowRays& row : rows) {
        lists.primary_hits += row.hits;
        lists.shadow.insert(lists.shadow.end(), row.shadow.begin(), row.shadow.end());
        lists.bounce.insert(lists.bounce.end(), row.bounce.begin(), row.bounce.end());
    }
    return lists;
}

}  // namespace isotrace::cli
