#pragma once
// The path tracer for up to eight samples of one pixel at once, on scenes of flat triangle meshes with constant
// Lambertian materials lit by isotropic point lights (RenderScene::flat_lambertian()): every ray an Embree packet
// query, the shading in eight SIMD lanes. Lane by lane it performs PathIntegrator::radiance's arithmetic in the
// same order, so it gives the same bits (tested); what it gains is the per-path overhead of the general loop (hit
// completion into a SurfaceHit, the BSDF variant, the virtual light and material calls), which on such scenes
// was about as large as Embree's own time (docs/decisions.md, "The path tracer: one path at a time, or eight
// in SIMD lanes").
//
// The kernel is built twice: into the library for baseline x86-64 and, for AVX2, into a module beside it that is
// loaded on CPUs that have AVX2 and FMA (a module, so that the inline functions it compiles for AVX2 stay its own;
// no contraction, so both round alike). flat_lambertian_kernel() picks one once.
#include <span>

#include "integrators/path/path_integrator.h"
#include "renderer/math/lanes.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {

using FlatLambertianKernel = void (*)(const PathSettings& settings, std::span<const Ray> camera_rays,
                                      const RenderScene& scene, const FlatLambertianScene& flat,
                                      std::span<SampleStream> samples, std::span<PrimaryHitRecord> primary,
                                      std::span<Rgb> radiance);

// The module's entry, FlatLambertianKernel(const char* isotrace_version): its kernel when the library's version is
// its own, else nullptr (avx2_module_build).
inline constexpr const char* kFlatLambertianKernelEntry = "isotrace_flat_lambertian_kernel";

// The AVX2 module's kernel where the CPU has AVX2 and the module loads, else the baseline one.
FlatLambertianKernel flat_lambertian_kernel();
// Which of them that is: "avx2" or "baseline x86-64".
const char* flat_lambertian_kernel_name();

namespace baseline_isa {
void trace_flat_lambertian_paths(const PathSettings& settings, std::span<const Ray> camera_rays,
                                 const RenderScene& scene, const FlatLambertianScene& flat,
                                 std::span<SampleStream> samples, std::span<PrimaryHitRecord> primary,
                                 std::span<Rgb> radiance);
}  // namespace baseline_isa

}  // namespace isotrace
