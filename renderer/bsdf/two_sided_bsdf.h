#pragma once
// Base of the opaque, reflection-only models (Lambert, conductor, coated diffuse). They are two-sided:
// shading happens on the side of wo, i.e. a wo below the surface (wo.z < 0) sees the mirror image of the
// upper-side response, and light is only scattered back into wo's hemisphere. A model derives from
// TwoSidedBsdf<itself> and provides the upper-side response:
//   Rgb eval_upper(wo, wi), float pdf_upper(wo, wi)   wo.z > 0 and wi.z > 0
//   sample_upper(wo, u_lobe, u)                       wo.z > 0; a result below the surface is discarded
#include "renderer/bsdf/bsdf.h"
#include "renderer/bsdf/shading_frame.h"

namespace isotrace {

template <class Model>
class TwoSidedBsdf {
public:
    // Zero when wo or wi lies in the surface plane or when wi is on the other side from wo. Reflection carries
    // radiance and importance alike, so `mode` does not matter.
    Rgb eval(const Vec3f& wo, const Vec3f& wi, TransportMode = TransportMode::Radiance) const {
        if (!same_hemisphere(wo, wi)) return {};
        return wo.z > 0 ? model().eval_upper(wo, wi) : model().eval_upper(mirror_z(wo), mirror_z(wi));
    }
    float pdf(const Vec3f& wo, const Vec3f& wi) const {
        if (!same_hemisphere(wo, wi)) return 0;
        return wo.z > 0 ? model().pdf_upper(wo, wi) : model().pdf_upper(mirror_z(wo), mirror_z(wi));
    }
    // Inlined into its caller (the path tracer's bounce): called, it returns the sample through memory, written a
    // field at a time, and the caller's one load of both flags with their padding waits until those byte stores
    // have retired (a failed store forwarding); inlined, the sample stays in registers.
    [[gnu::always_inline]] std::optional<BsdfSample> sample(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                                            TransportMode = TransportMode::Radiance) const {
        if (wo.z == 0) return std::nullopt;
        const bool below = wo.z < 0;
        std::optional<BsdfSample> sample = model().sample_upper(below ? mirror_z(wo) : wo, u_lobe, u);
        if (!sample || !(sample->wi.z > 0)) return std::nullopt;
        if (below) sample->wi = mirror_z(sample->wi);
        return sample;
    }

private:
    const Model& model() const { return static_cast<const Model&>(*this); }
};

}  // namespace isotrace
