#include "renderer/bsdf/two_sided_bsdf.h"

#include "renderer/bsdf/shading_frame.h"

namespace isotrace {

Rgb TwoSidedBsdf::eval(const Vec3f& wo, const Vec3f& wi, TransportMode) const {
    if (!same_hemisphere(wo, wi)) return {};
    return wo.z > 0 ? eval_upper(wo, wi) : eval_upper(mirror_z(wo), mirror_z(wi));
}

float TwoSidedBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
    if (!same_hemisphere(wo, wi)) return 0;
    return wo.z > 0 ? pdf_upper(wo, wi) : pdf_upper(mirror_z(wo), mirror_z(wi));
}

std::optional<BsdfSample> TwoSidedBsdf::sample(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                               TransportMode) const {
    if (wo.z == 0) return std::nullopt;
    const bool below = wo.z < 0;
    std::optional<BsdfSample> sample = sample_upper(below ? mirror_z(wo) : wo, u_lobe, u);
    if (!sample || !(sample->wi.z > 0)) return std::nullopt;
    if (below) sample->wi = mirror_z(sample->wi);
    return sample;
}

}  // namespace isotrace
