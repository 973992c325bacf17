#include "geometry/abm_patch/smooth_joins.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "geometry/curves/curve_interpolation.h"

namespace isotrace {
namespace {

// Least reach, as a fraction of the secant across the patch: a patch turned by 75° and more into the shared plane
// keeps this much rather than folding into a cusp.
constexpr double kLeastRibbonReach = 0.25;

struct SideUse {
    std::size_t patch, side;
};

// The plane of the two curves meeting at corner k of the patch (normal to the incoming and the outgoing tangent),
// facing the patch's front; where the tangents are parallel, the patch's own corner normal.
Vec3d corner_plane_normal(const AbmPatch& patch, int corner) {
    const std::vector<PatchSide>& sides = patch.sides();
    const int n = int(sides.size());
    const Vec3d incoming = sides[std::size_t((corner + n - 1) % n)].point_and_tangent(1).second;
    const Vec3d outgoing = sides[std::size_t(corner)].point_and_tangent(0).second;
    const Vec3d own = patch.corner_normal(corner);
    const Vec3d plane = cross(incoming, outgoing);
    if (!(length(plane) > 1e-6 * length(incoming) * length(outgoing))) return own;
    return dot(plane, own) < 0 ? -1.0 * normalize(plane) : normalize(plane);
}

// What a side sees of its patch at λ: the tangent and the secant from the side's point to the patch's centre,
// across the side (without its part along the tangent), per unit of domain distance.
struct SideView {
    Vec3d tangent, secant;
};

SideView view(const AbmPatch& patch, std::size_t side, double along) {
    const DomainPoint centre = patch.domain().centre();
    Footprint footprints[PatchDomain::kMaxSides];
    patch.domain().footprints(centre, footprints);
    const PatchSide& s = patch.sides()[side];
    const Vec3d tangent = side_direction(*s.curve, s.reversed, along);
    const Vec3d toward = patch(centre) - s.point(along);
    return {tangent, (1 / footprints[side].distance) * (toward - dot(toward, tangent) * tangent)};
}

// The patch's plane along its side, as the side sees it: spanned by the tangent and the secant, facing the front.
Vec3d secant_normal(const AbmPatch& patch, std::size_t side, double along) {
    const SideView v = view(patch, side, along);
    return safe_normalize(cross(v.tangent, v.secant), patch.side_normal(int(side), along));
}

}  // namespace

std::vector<AbmPatch> with_smooth_joins(const std::vector<AbmPatch>& patches) {
    std::map<const SpaceCurve*, std::vector<SideUse>> uses;
    for (std::size_t p = 0; p < patches.size(); ++p)
        for (std::size_t i = 0; i < patches[p].sides().size(); ++i) uses[patches[p].sides()[i].curve.get()].push_back({p, i});

    std::vector<std::vector<PatchSide>> sides;
    for (const AbmPatch& patch : patches) sides.push_back(patch.sides());
    for (const auto& [curve, users] : uses) {
        if (users.size() != 2 || users[0].patch == users[1].patch) continue;
        for (const SideUse& use : users)
            if (!(patches[use.patch].exponent() > 1))
                throw std::invalid_argument("patch " + std::to_string(use.patch) +
                                            ": smooth joins need a weight exponent p > 1 (with p = 1 the other curves "
                                            "pull the surface off the shared tangent plane)");
        const SideUse a = users[0], b = users[1];
        const AbmPatch &patch_a = patches[a.patch], &patch_b = patches[b.patch];
        const bool reversed_a = patch_a.sides()[a.side].reversed, reversed_b = patch_b.sides()[b.side].reversed;
        // Opposite directions: the fronts are on the same side and the normals add; otherwise B's is flipped.
        const double b_facing = reversed_a != reversed_b ? 1 : -1;
        auto mean = [&](const Vec3d& na, const Vec3d& nb) { return safe_normalize(na + b_facing * nb, na); };
        const int samples =
            std::clamp(4 * int(curve->control_points().size()), kRibbonSamples, int(kMaxInterpolatedPoints) - 1);
        // N(t), facing A's front: the mean of the two patches' planes along the curve, shifted at the ends (fading
        // linearly) to the mean of their corner planes there, so that where the curves meeting at a corner lie in
        // one plane, every curve's N is that plane's normal.
        auto plane_mean = [&](double t) {
            return mean(secant_normal(patch_a, a.side, reversed_a ? 1 - t : t), secant_normal(patch_b, b.side, reversed_b ? 1 - t : t));
        };
        auto corner_mean = [&](double t) {
            auto corner = [&](const AbmPatch& patch, const SideUse& use, bool reversed) {
                const bool start = (t == 0) != reversed;  // the side's start: its corner; its end: the next one
                return corner_plane_normal(patch, int((use.side + (start ? 0 : 1)) % patch.sides().size()));
            };
            return mean(corner(patch_a, a, reversed_a), corner(patch_b, b, reversed_b));
        };
        const Vec3d shift0 = corner_mean(0) - plane_mean(0), shift1 = corner_mean(1) - plane_mean(1);
        std::vector<Vec3d> normal;
        std::vector<double> parameters;
        for (int k = 0; k <= samples; ++k) {
            const double t = double(k) / samples;
            normal.push_back(plane_mean(t) + (1 - t) * shift0 + t * shift1);
            parameters.push_back(t);
        }
        const auto shared = std::make_shared<const BSplineCurve<Vec3d>>(interpolate_curve(normal, parameters, 3));
        for (const SideUse& use : users) {
            const AbmPatch& patch = patches[use.patch];
            const PatchSide& side = patch.sides()[use.side];
            const double facing = use.patch == a.patch ? 1 : b_facing;
            std::vector<double> reach;
            for (int k = 0; k <= samples; ++k) {
                const double lambda = parameters[std::size_t(k)];
                const SideView v = view(patch, use.side, lambda);
                const Vec3d n = facing * (*shared)(side.reversed ? 1 - lambda : lambda);
                const Vec3d inward = inward_across(n, v.tangent, safe_normalize(v.secant, Vec3d{}));
                // Turned by φ into the shared plane, the secant's reach shrinks by cos φ: a patch tilted up by φ
                // then rises about as much as a circular arc would.
                reach.push_back(std::max(dot(v.secant, inward), kLeastRibbonReach * length(v.secant)));
            }
            sides[use.patch][use.side].ribbon = std::make_shared<const CrossTangent>(
                side.curve, side.reversed, shared, facing, interpolate_curve(reach, parameters, 3));
        }
    }
    std::vector<AbmPatch> result;
    for (std::size_t p = 0; p < patches.size(); ++p) result.push_back(patches[p].with_sides(std::move(sides[p])));
    return result;
}

}  // namespace isotrace
