#pragma once
// The secondary rays of isotrace bench, built once (untimed) from one scene's primary hits so that the direct and
// the tessellated scene trace exactly the same rays: a shadow ray towards a fixed point light and one
// cosine-distributed diffuse bounce per pixel whose centre ray hits something.
#include <vector>

#include "renderer/core/ray.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace::cli {

struct SecondaryRayLists {
    // The point light: centre of the top face of the objects' bounds (their shapes' own, not Embree's), raised by their
    // height.
    Vec3f light;
    std::size_t primary_hits = 0;
    std::vector<Ray> shadow;  // for the occlusion query, ending just short of the light
    std::vector<Ray> bounce;  // for the nearest-hit query, unbounded
};

// Both lists in pixel order (row-major over the crop window), identical across thread counts. As the integrators
// do, normals are turned towards the camera, every ray starts at SurfaceHit::spawn_origin (a shadow ray is
// shadow_ray's, aimed at the light from there), and a hit gets no shadow ray when the light is behind its surface
// and no bounce when the sampled direction (around the shading normal) falls below the geometric surface. The
// bounce direction of pixel (x, y) comes from an IndependentSampler with the scene's seed, sample 0, dimensions 0
// and 1. `clearance` (world units) pushes every origin that much further off along the geometric normal: a
// tessellation of the hit surface strays from it by up to about a cell, and a ray starting within that band would
// hit the mesh at once where the exact surface lets it go. Throws InputError when the scene's bounds are empty.
SecondaryRayLists build_secondary_rays(const LoadedScene& scene, float clearance = 0);

}  // namespace isotrace::cli
