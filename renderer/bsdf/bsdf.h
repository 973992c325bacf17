#pragma once
// The scattering models in this folder (LambertBsdf, ConductorBsdf, DielectricBsdf, CoatedDiffuseBsdf,
// PrincipledBsdf) describe how a surface scatters light, in the local shading frame (z = shading normal).
// Directions are unit vectors pointing away from the surface: wo towards the viewer / previous path vertex, wi
// towards the light / next vertex. Each model has the same members, called without virtual dispatch (SurfaceBsdf
// holds one by value):
//   Rgb eval(wo, wi, mode)         f(wo, wi) without the cosine; 0 for delta lobes
//   float pdf(wo, wi)              solid-angle density with which sample() returns wi (its non-delta part)
//   sample(wo, u_lobe, u, mode)    u_lobe picks a lobe, u the direction within it; empty when none is produced
//   bool has_delta_lobe()          some lobe is a Dirac delta (light sampling cannot reach it)
//   bool is_fully_delta()          every lobe is a Dirac delta (light sampling is useless)
//   bool chooses_lobe()            sample() reads u_lobe (it picks one of several lobes); false: u_lobe is ignored
#include <array>
#include <cmath>
#include <optional>

#include "renderer/math/rgb.h"
#include "renderer/math/vec3.h"

namespace isotrace {

// What the path carries. Refraction compresses radiance by (eta_t / eta_i)^2 but not importance, so only
// Radiance applies the 1/eta^2 factor to transmission (Veach 1997, section 5.2).
enum class TransportMode { Radiance, Importance };

struct BsdfSample {
    Rgb weight;                    // f(wo,wi) |cos(wi)| / pdf; for a delta lobe, the lobe's weight
    Vec3f wi;
    float pdf = 0;                 // per solid angle; for a delta lobe, the probability of choosing it
    bool is_delta = false;
    bool is_transmission = false;
    float eta = 1;                 // IOR on wi's side over IOR on wo's side (1 for reflection), for Russian roulette
};

// The sample of a non-delta lobe towards wi, its weight and pdf taken from model.eval() and model.pdf() so the
// three can never disagree. Empty when the pdf is zero (wi unreachable, e.g. lost to rounding at a horizon).
// `eta` is BsdfSample::eta for a transmitted wi.
template <class Model>
std::optional<BsdfSample> sample_towards(const Model& model, const Vec3f& wo, const Vec3f& wi, TransportMode mode,
                                         float eta = 1) {
    const float pdf = model.pdf(wo, wi);
    if (!(pdf > 0)) return std::nullopt;
    const bool is_transmission = wo.z * wi.z < 0;
    BsdfSample sample;
    sample.weight = model.eval(wo, wi, mode) * (std::abs(wi.z) / pdf);
    sample.wi = wi;
    sample.pdf = pdf;
    sample.is_transmission = is_transmission;
    sample.eta = is_transmission ? eta : 1.0f;
    return sample;
}

}  // namespace isotrace
