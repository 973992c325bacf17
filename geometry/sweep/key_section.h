#pragma once
// Key cross-sections of a sweep. A key section is a centre, an orientation (its plane is the local xy plane,
// its normal N the local z axis) and radii r_j sampled at θ_j = 2πj/m in the local frame. Users edit them in
// relative form — each key stored in the frame of the one before — so that moving or turning key k carries keys
// k+1 … n along (the paper's Fig. 2).
#include <vector>

#include "renderer/math/quaternion.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct KeySection {
    Vec3d centre;
    Quaternion orientation = Quaternion::identity();  // unit
    std::vector<double> radii;                        // m ≥ 3 values > 0 at θ_j = 2πj/m
};

// Key k relative to key k−1 (key 0 relative to the world): centre_k = centre_{k−1} + R_{k−1}·offset and
// orientation_k = orientation_{k−1}·rotation.
struct RelativeKeySection {
    Vec3d offset;
    Quaternion rotation = Quaternion::identity();
    std::vector<double> radii;
};

// An edit of one key section in its own frame.
struct KeyEdit {
    Vec3d translate;                             // in the key's local frame
    Quaternion rotate = Quaternion::identity();  // applied in the key's local frame
    double radius_scale = 1;                     // multiplies the key section's radii
    double radius_offset = 0;                    // then added to every radius sample
};

// Applies `edit` to key `key` of a relative chain: the key sections after it move along (Fig. 2).
void edit_key_section(std::vector<RelativeKeySection>& chain, std::size_t key, const KeyEdit& edit);

std::vector<KeySection> to_absolute(const std::vector<RelativeKeySection>& relative);
std::vector<RelativeKeySection> to_relative(const std::vector<KeySection>& absolute);

}  // namespace isotrace
