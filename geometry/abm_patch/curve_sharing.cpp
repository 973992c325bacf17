#include "geometry/abm_patch/curve_sharing.h"

#include <algorithm>
#include <map>

#include "geometry/abm_patch/loop_check.h"

namespace isotrace {
namespace {

// A distinct curve, where it is first used.
struct FirstUse {
    const SpaceCurve* curve;
    std::shared_ptr<const SpaceCurve> shared;
    std::size_t patch, side;
    double length;
};

// Where two curves stand to each other: how far apart they are at equal parameters, with `other` run backwards
// when that brings its ends closer.
struct Comparison {
    double end_gap, gap;
    bool flipped;
};

Comparison compare(const SpaceCurve& curve, const SpaceCurve& other) {
    const Vec3d a0 = curve(0), a1 = curve(1), b0 = other(0), b1 = other(1);
    const double same = std::max(length(a0 - b0), length(a1 - b1)), flipped = std::max(length(a0 - b1), length(a1 - b0));
    Comparison result{std::min(same, flipped), 0, flipped < same};
    for (int k = 0; k <= kCurveComparisonSamples; ++k) {
        const double t = double(k) / kCurveComparisonSamples;
        result.gap = std::max(result.gap, length(curve(t) - other(result.flipped ? 1 - t : t)));
    }
    return result;
}

// Sorting key that does not change when a curve is run backwards; curves with nearly equal ends have nearly equal keys.
double end_key(const SpaceCurve& curve) { return curve(0).x + curve(1).x; }

}  // namespace

std::vector<AbmPatch> share_coincident_curves(const std::vector<AbmPatch>& patches, double tolerance) {
    std::vector<FirstUse> uses;
    std::multimap<double, std::size_t> by_key;  // end_key → index into uses
    // Each distinct curve: the curve it becomes and whether it runs backwards along it.
    std::map<const SpaceCurve*, std::pair<std::shared_ptr<const SpaceCurve>, bool>> replacement;
    for (std::size_t p = 0; p < patches.size(); ++p)
        for (std::size_t i = 0; i < patches[p].sides().size(); ++i) {
            const PatchSide& side = patches[p].sides()[i];
            const SpaceCurve& curve = *side.curve;
            if (replacement.count(&curve)) continue;
            replacement[&curve] = {side.curve, false};
            const double length = curve.polyline_length(kCurveComparisonSamples);
            const double near = std::max(kNearlySharedFraction * length, tolerance);
            const double key = end_key(curve);
            // Ends within `near` of each other move the key by at most 2·near.
            for (auto it = by_key.lower_bound(key - 2 * near); it != by_key.end() && it->first <= key + 2 * near; ++it) {
                const FirstUse& earlier = uses[it->second];
                if (earlier.patch == p) continue;
                const double limit = std::max(kNearlySharedFraction * std::min(length, earlier.length), tolerance);
                const Comparison c = compare(*earlier.curve, curve);
                if (c.end_gap > limit || c.gap > limit) continue;
                if (c.gap <= tolerance) {
                    replacement[&curve] = {earlier.shared, c.flipped};
                    break;
                }
                const PatchSide& first = patches[earlier.patch].sides()[earlier.side];
                throw NearlySharedCurve(
                    p, i,
                    side.name + " of patch " + std::to_string(p) + " nearly coincides with " + first.name + " of patch " +
                        std::to_string(earlier.patch) + ": they differ by up to " + format_number(c.gap) +
                        " (closure_tolerance " + format_number(tolerance) +
                        "), which would leave a crack between the patches; give both patches the same curve (name it "
                        "in \"curves\") or make the two identical");
            }
            if (replacement[&curve].first.get() == &curve) {
                by_key.emplace(key, uses.size());
                uses.push_back({&curve, side.curve, p, i, length});
            }
        }
    std::vector<AbmPatch> result;
    for (const AbmPatch& patch : patches) {
        std::vector<PatchSide> sides = patch.sides();
        for (PatchSide& side : sides) {
            const auto& [curve, flipped] = replacement.at(side.curve.get());
            side.curve = curve;
            side.reversed = side.reversed != flipped;
        }
        result.push_back(patch.with_sides(std::move(sides)));
    }
    return result;
}

}  // namespace isotrace
