#pragma once
// Multi-resolution sweeps after Forsey & Bartels' hierarchical refinement (the paper's §4.3, Fig. 6). Level 1
// holds the user's key sections (relative form). Each finer level ℓ + 1 doubles the key sections — at the
// parameters of level ℓ's keys and half-way between them — and stores every one of them as an offset from the
// level-ℓ sweep at its parameter s: a centre offset in the section frame R_ℓ(s), an orientation offset
// q_ℓ(s)⁻¹·q and additive radius offsets. All offsets start at zero, so every level first reproduces the one
// below it. Editing a level changes its offsets (or, at level 1, its key sections); because finer offsets are
// relative to the coarser sweep, a fine edit rides along with any later coarse edit instead of being undone.
#include <vector>

#include "geometry/sweep/key_section.h"
#include "geometry/sweep/sweep_surface.h"

namespace isotrace {

class MultiResolutionSweep {
public:
    static constexpr int kMaxLevels = 6;

    // `levels` ≥ 1 (at most kMaxLevels). Throws std::invalid_argument for bad key sections (SweepSurface) or levels.
    MultiResolutionSweep(const std::vector<KeySection>& keys, int levels, SweepSpline spline = SweepSpline::cubic);

    int levels() const { return int(offsets_.size()) + 1; }
    // Key sections of level ℓ (1-based): the user's keys at level 1, 2^(ℓ−1)·(n − 1) + 1 keys at level ℓ.
    int key_count(int level) const;
    // The sweep through level ℓ's key sections with every offset of levels 2…ℓ applied.
    SweepSurface surface(int level) const;
    SweepSurface finest() const { return surface(levels()); }

    // Throws std::invalid_argument "level"/"key" when out of range. The edit of a level-1 key carries the keys
    // after it along (relative key sections, Fig. 2); at finer levels it changes that key's offset only.
    void edit(int level, int key, const KeyEdit& edit);

private:
    struct Offset {
        double s = 0;  // parameter on the coarser sweep
        Vec3d centre;
        Quaternion orientation = Quaternion::identity();
        std::vector<double> radii;  // additive, one per radius sample
    };
    std::vector<KeySection> keys_at(int level) const;

    std::vector<RelativeKeySection> base_;
    SweepSpline spline_;
    std::vector<std::vector<double>> parameters_;  // [level − 1]: the keys' t, fixed when the levels are made
    std::vector<std::vector<Offset>> offsets_;  // [level − 2][key]
};

}  // namespace isotrace
