#pragma once
// Bsdf: how a surface scatters light, in the local shading frame (z = shading normal). Directions are unit
// vectors pointing away from the surface: wo towards the viewer / previous path vertex, wi towards the light /
// next vertex. Materials build one of the models in this folder per shading point.
#include <array>
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

class Bsdf {
public:
    virtual ~Bsdf() = default;
    // f(wo, wi) without the cosine; 0 for delta lobes.
    virtual Rgb eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode = TransportMode::Radiance) const = 0;
    // Solid-angle density with which sample() returns wi (its non-delta part); 0 for delta lobes.
    virtual float pdf(const Vec3f& wo, const Vec3f& wi) const = 0;
    // u_lobe picks a lobe, u the direction within it. Empty when no direction is produced.
    virtual std::optional<BsdfSample> sample(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                             TransportMode mode = TransportMode::Radiance) const = 0;
    // Some lobe is a Dirac delta (light sampling cannot reach it).
    virtual bool has_delta_lobe() const = 0;
    // Every lobe is a Dirac delta (light sampling is useless).
    virtual bool is_fully_delta() const = 0;
};

// The sample of a non-delta lobe towards wi, its weight and pdf taken from bsdf.eval() and bsdf.pdf() so the
// three can never disagree. Empty when the pdf is zero (wi unreachable, e.g. lost to rounding at a horizon).
// `eta` is BsdfSample::eta for a transmitted wi.
std::optional<BsdfSample> sample_towards(const Bsdf& bsdf, const Vec3f& wo, const Vec3f& wi, TransportMode mode,
                                         float eta = 1);

}  // namespace isotrace
