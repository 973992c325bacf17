#pragma once
// The material where the parts of one surface blend into each other (blob elements with materials of their own):
// at a hit, the parts' principled parameters mixed by the parts' shares of the field there (SurfaceHit::blend), so
// that colour, roughness, metallic … flow across the neck where two elements merge. Lobes mix as their parameters
// do (half metallic = half metal, half dielectric); emission and albedo mix linearly; bump and normal maps mix
// their normals.
#include <memory>
#include <vector>

#include "renderer/plugin/material.h"

namespace isotrace {

// `parts[i]` is the material of part i (SurfaceHit::blend indexes them); every one can_blend().
std::unique_ptr<Material> make_blended_material(std::vector<const Material*> parts);

}  // namespace isotrace
