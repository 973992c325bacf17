#pragma once
// The path tracer for up to eight samples of one pixel at once, on scenes of flat triangle meshes with constant
// Lambertian materials lit by isotropic point lights (RenderScene::flat_lambertian()): every ray an Embree packet
// query, the shading in eight SIMD lanes. Lane by lane it performs PathIntegrator::radiance's arithmetic in the
// same order, so it gives the same bits (tested); what it gains is the per-path overhead of the general loop (hit
// completion into a SurfaceHit, the BSDF variant, the virtual light and material calls), which on such scenes
// was about as large as Embree's own time (docs/benchmarks.md, issue 14).
#include <span>

#include "integrators/path/path_integrator.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {

void trace_flat_lambertian_paths(const PathSettings& settings, std::span<const Ray> camera_rays,
                                 const RenderScene& scene, const FlatLambertianScene& flat,
                                 std::span<SampleStream> samples, std::span<PrimaryHitRecord> primary,
                                 std::span<Rgb> radiance);

}  // namespace isotrace
