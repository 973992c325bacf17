#include "geometry/implicit/surface_region.h"

#include <bit>
#include <limits>
#include <memory>

#include "geometry/implicit/unit_piece_lanes.h"

namespace isotrace {
namespace surface_region_detail {

MetaballLanes::MetaballLanes(std::span<const Metacube> elements, const FieldPiece& unit,
                             std::span<const std::uint32_t> ids)
    : coefficients_(unit.coefficients), per_level_((ids.size() + 3) / 4 * 4),
      lanes_(std::make_unique_for_overwrite<double[]>((kHalvings + 2) * kFields * per_level_)),
      counts_(kHalvings + 2), levels_(kHalvings + 2), reaching_(per_level_ / 4) {
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const Metacube& element = elements[ids[i]];
        lanes(0, kX)[i] = element.centre().x;
        lanes(0, kY)[i] = element.centre().y;
        lanes(0, kZ)[i] = element.centre().z;
        lanes(0, kInverseRadius2)[i] = 1 / (element.radius() * element.radius());
        lanes(0, kWeight)[i] = element.weight();
    }
    counts_[0] = ids.size();
    levels_[0] = 0;
    make_inert(0, ids.size());
}

void MetaballLanes::make_inert(int h, std::size_t first) {
    for (std::size_t lane = first; lane < (first + 3) / 4 * 4; ++lane) {
        for (int field = 0; field < kFields; ++field) lanes(h, Field(field))[lane] = 0;
        lanes(h, kInverseRadius2)[lane] = std::numeric_limits<double>::infinity();  // x is ∞ or NaN: never reaches
    }
}

FieldBounds MetaballLanes::bounds(const WorldBounds& box, int h) {
    const std::size_t count = counts_[std::size_t(h)];
    Double4 low{}, high{}, scale{};
    std::size_t kept = 0;
    for (std::size_t first = 0; first < count; first += 4) {
        Double4 near2{}, far2{};
        for (int k = 0; k < 3; ++k) {
            const Double4 centre = load4(lanes(h, Field(kX + k)) + first);
            const Double4 below = box.lower[k] - centre, above = centre - box.upper[k];
            const Double4 gap = max4(max4(below, above), Double4{});  // as Metacube::nearest_squared_distance
            const Double4 reach = max4(abs4(below), abs4(above));      // as Metacube::farthest_squared_distance
            near2 += gap * gap;
            far2 += reach * reach;
        }
        const Double4 inverse_radius2 = load4(lanes(h, kInverseRadius2) + first);
        const Double4 weight = load4(lanes(h, kWeight) + first);
        const Double4 x_near = near2 * inverse_radius2, x_far = far2 * inverse_radius2;
        const Mask4 reaches = x_near < 1.0;  // inert lanes never do
        const Double4 strongest = unit_piece_value(coefficients_, x_near, BoundMulAdd{}),
                      weakest = unit_piece_value(coefficients_, x_far, BoundMulAdd{});
        const Mask4 positive = weight >= 0.0;
        low += select(reaches, weight * select(positive, weakest, strongest), Double4{});
        high += select(reaches, weight * select(positive, strongest, weakest), Double4{});
        scale += select(reaches, abs4(weight), Double4{});
        reaching_[first / 4] = mask_bits(reaches);
        kept += std::size_t(std::popcount(reaching_[first / 4]));
    }
    counts_[std::size_t(h + 1)] = kept;
    if (kept == count) {
        levels_[std::size_t(h + 1)] = levels_[std::size_t(h)];  // every element reaches the sub-box: share the lanes
    } else {
        // The lanes that reach, compacted in order into the next level's own lanes, without a branch per lane.
        levels_[std::size_t(h + 1)] = std::size_t(h + 1);
        std::size_t to = 0;
        for (std::size_t first = 0; first < count; first += 4)
            for (std::size_t lane = 0; lane < 4; ++lane) {
                for (int field = 0; field < kFields; ++field)
                    lanes(h + 1, Field(field))[to] = lanes(h, Field(field))[first + lane];
                to += (reaching_[first / 4] >> lane) & 1u;
            }
        make_inert(h + 1, kept);
    }
    return {lane_sum(low), lane_sum(high), lane_sum(scale)};
}

std::optional<WorldBounds> padded_region(const std::optional<WorldBounds>& region, const WorldBounds& box) {
    if (!region) return std::nullopt;
    const Vec3d padding = (box.upper - box.lower) * kRelativePadding;
    return WorldBounds{max(region->lower - padding, box.lower), min(region->upper + padding, box.upper)};
}

}  // namespace surface_region_detail

std::optional<WorldBounds> metaball_surface_region(const WorldBounds& box, std::span<const std::uint32_t> ids,
                                                   std::span<const Metacube> elements, const FieldPiece& unit,
                                                   double threshold) {
    using namespace surface_region_detail;
    MetaballLanes lanes(elements, unit, ids);
    return padded_region(straddling_bounds(lanes, box, threshold), box);
}

}  // namespace isotrace
