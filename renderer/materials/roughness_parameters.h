#pragma once
// Roughness of microfacet materials as written in scenes: "roughness" in [0, 1] (perceptual, alpha =
// roughness^2; 0 = perfectly smooth), optionally "roughness_v" for an anisotropic second axis.
#include "renderer/params/scene_node.h"

namespace isotrace {

struct MicrofacetAlphas {
    float x = 0, y = 0;  // both 0 = smooth
};

MicrofacetAlphas parse_roughness(const SceneNode& node, double default_roughness);

}  // namespace isotrace
