#pragma once
// Base of the opaque, reflection-only models (Lambert, conductor, coated diffuse). They are two-sided:
// shading happens on the side of wo, i.e. a wo below the surface (wo.z < 0) sees the mirror image of the
// upper-side response, and light is only scattered back into wo's hemisphere.
#include "renderer/bsdf/bsdf.h"

namespace isotrace {

class TwoSidedBsdf : public Bsdf {
public:
    // Zero when wo or wi lies in the surface plane or when wi is on the other side from wo. Reflection carries
    // radiance and importance alike, so `mode` does not matter.
    Rgb eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode = TransportMode::Radiance) const final;
    float pdf(const Vec3f& wo, const Vec3f& wi) const final;
    std::optional<BsdfSample> sample(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                     TransportMode mode = TransportMode::Radiance) const final;

protected:
    // The upper-side response: wo.z > 0 and wi.z > 0.
    virtual Rgb eval_upper(const Vec3f& wo, const Vec3f& wi) const = 0;
    virtual float pdf_upper(const Vec3f& wo, const Vec3f& wi) const = 0;
    // wo.z > 0; the result may lie below the surface (then it is discarded).
    virtual std::optional<BsdfSample> sample_upper(const Vec3f& wo, float u_lobe, std::array<float, 2> u) const = 0;
};

}  // namespace isotrace
