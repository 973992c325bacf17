#include "geometry/sweep/key_section.h"

namespace isotrace {

std::vector<KeySection> to_absolute(const std::vector<RelativeKeySection>& relative) {
    std::vector<KeySection> absolute;
    for (const RelativeKeySection& key : relative) {
        KeySection k;
        if (absolute.empty()) {
            k.centre = key.offset;
            k.orientation = normalize(key.rotation);
        } else {
            const KeySection& previous = absolute.back();
            k.centre = previous.centre + previous.orientation.rotate(key.offset);
            k.orientation = normalize(previous.orientation * key.rotation);
        }
        k.radii = key.radii;
        absolute.push_back(std::move(k));
    }
    return absolute;
}

std::vector<RelativeKeySection> to_relative(const std::vector<KeySection>& absolute) {
    std::vector<RelativeKeySection> relative;
    for (std::size_t k = 0; k < absolute.size(); ++k) {
        RelativeKeySection r;
        if (k == 0) {
            r.offset = absolute[k].centre;
            r.rotation = absolute[k].orientation;
        } else {
            const Quaternion& previous = absolute[k - 1].orientation;
            r.offset = previous.rotate_back(absolute[k].centre - absolute[k - 1].centre);
            r.rotation = previous.conjugate() * absolute[k].orientation;
        }
        r.radii = absolute[k].radii;
        relative.push_back(std::move(r));
    }
    return relative;
}

void edit_key_section(std::vector<RelativeKeySection>& chain, std::size_t key, const KeyEdit& edit) {
    RelativeKeySection& k = chain[key];
    // The offset is in the previous key's frame, the translation in this key's own frame.
    const Quaternion previous = key == 0 ? Quaternion::identity() : to_absolute(chain)[key - 1].orientation;
    const Quaternion own = previous * k.rotation;
    k.offset = k.offset + previous.rotate_back(own.rotate(edit.translate));
    k.rotation = normalize(k.rotation * edit.rotate);
    for (double& r : k.radii) r = r * edit.radius_scale + edit.radius_offset;
}

}  // namespace isotrace
