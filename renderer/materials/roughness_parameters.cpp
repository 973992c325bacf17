#include "renderer/materials/roughness_parameters.h"

#include "renderer/bsdf/ggx.h"

namespace isotrace {

MicrofacetAlphas parse_roughness(const SceneNode& node, double default_roughness) {
    const double u = node.number_or("roughness", default_roughness, NumberRange::unit_interval());
    const double v = node.number_or("roughness_v", u, NumberRange::unit_interval());
    if ((u == 0) != (v == 0)) node.fail_at("roughness_v", "a smooth surface needs both roughness values at 0");
    if (u == 0) return {};
    return {roughness_to_alpha(float(u)), roughness_to_alpha(float(v))};
}

}  // namespace isotrace
