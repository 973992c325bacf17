#include "renderer/bsdf/bsdf.h"

#include <cmath>

namespace isotrace {

std::optional<BsdfSample> sample_towards(const Bsdf& bsdf, const Vec3f& wo, const Vec3f& wi, TransportMode mode,
                                         float eta) {
    const float pdf = bsdf.pdf(wo, wi);
    if (!(pdf > 0)) return std::nullopt;
    const bool is_transmission = wo.z * wi.z < 0;
    BsdfSample sample;
    sample.weight = bsdf.eval(wo, wi, mode) * (std::abs(wi.z) / pdf);
    sample.wi = wi;
    sample.pdf = pdf;
    sample.is_transmission = is_transmission;
    sample.eta = is_transmission ? eta : 1.0f;
    return sample;
}

}  // namespace isotrace
