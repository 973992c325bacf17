#include "geometry/sweep/multi_resolution_sweep.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace isotrace {

MultiResolutionSweep::MultiResolutionSweep(const std::vector<KeySection>& keys, int levels, SweepSpline spline)
    : spline_(spline) {
    if (levels < 1 || levels > kMaxLevels)
        throw std::invalid_argument("levels: must be in [1, " + std::to_string(kMaxLevels) + "], got " +
                                    std::to_string(levels));
    base_ = to_relative(keys);
    parameters_.push_back(SweepSurface(keys).key_parameters());  // also validates the key sections
    for (int level = 2; level <= levels; ++level) {
        const SweepSurface coarse = surface(level - 1);
        const std::vector<double>& t = coarse.key_parameters();
        std::vector<Offset> offsets;
        for (std::size_t k = 0; k < t.size(); ++k) {
            if (k > 0) offsets.push_back({(t[k - 1] + t[k]) / 2, {}, Quaternion::identity(), {}});
            offsets.push_back({t[k], {}, Quaternion::identity(), {}});
        }
        for (Offset& o : offsets) o.radii.assign(keys.front().radii.size(), 0.0);
        offsets_.push_back(std::move(offsets));
        parameters_.push_back(SweepSurface(keys_at(level)).key_parameters());
    }
}

int MultiResolutionSweep::key_count(int level) const {
    if (level < 1 || level > levels()) return 0;
    return level == 1 ? int(base_.size()) : int(offsets_[std::size_t(level - 2)].size());
}

std::vector<KeySection> MultiResolutionSweep::keys_at(int level) const {
    if (level == 1) return to_absolute(base_);
    const SweepSurface coarse = surface(level - 1);
    const int m = coarse.radius_samples();
    std::vector<KeySection> keys;
    for (const Offset& o : offsets_[std::size_t(level - 2)]) {
        const Quaternion frame = coarse.orientation(o.s);
        KeySection key{coarse.centre(o.s) + frame.rotate(o.centre), normalize(frame * o.orientation), {}};
        for (int j = 0; j < m; ++j)
            key.radii.push_back(coarse.radius(2 * std::numbers::pi * j / m, o.s) + o.radii[std::size_t(j)]);
        keys.push_back(std::move(key));
    }
    return keys;
}

SweepSurface MultiResolutionSweep::surface(int level) const {
    if (level < 1 || level > levels())
        throw std::invalid_argument("level: must be in [1, " + std::to_string(levels()) + "], got " + std::to_string(level));
    return SweepSurface(keys_at(level), parameters_[std::size_t(level - 1)], spline_);
}

void MultiResolutionSweep::edit(int level, int key, const KeyEdit& e) {
    if (level < 1 || level > levels())
        throw std::invalid_argument("level: must be in [1, " + std::to_string(levels()) + "], got " + std::to_string(level));
    if (key < 0 || key >= key_count(level))
        throw std::invalid_argument("key: level " + std::to_string(level) + " has key sections 0 to " +
                                    std::to_string(key_count(level) - 1) + ", got " + std::to_string(key));
    if (level == 1) {
        edit_key_section(base_, std::size_t(key), e);
        return;
    }
    Offset& o = offsets_[std::size_t(level - 2)][std::size_t(key)];
    const SweepSurface coarse = surface(level - 1);
    const int m = coarse.radius_samples();
    o.centre = o.centre + o.orientation.rotate(e.translate);
    o.orientation = normalize(o.orientation * e.rotate);
    for (int j = 0; j < m; ++j) {
        const double base = coarse.radius(2 * std::numbers::pi * j / m, o.s) + o.radii[std::size_t(j)];
        o.radii[std::size_t(j)] = base * e.radius_scale + e.radius_offset - coarse.radius(2 * std::numbers::pi * j / m, o.s);
    }
}

}  // namespace isotrace
