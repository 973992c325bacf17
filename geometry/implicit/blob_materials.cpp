#include "geometry/implicit/blob_materials.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "renderer/core/inline_vector.h"

namespace isotrace {
namespace {

constexpr double kHardCubeReach = 1e-5;        // see the header: the face of a hard cube, within rounding
constexpr std::int64_t kWeightUnits = 1 << 20;  // the weights' resolution: sums of these stay exact in float

struct Share {
    std::uint32_t part;
    double value;
};

double term_of(const Metacube& element, const Vec3d& point, double term) {
    if (!element.is_hard_cube()) return term;
    const double reach = kHardCubeReach * (element.half_diagonal() + max_component(abs(point)));
    return element.distance_squared(point) <= reach * reach ? element.weight() : 0;
}

}  // namespace

BlobMaterials::BlobMaterials(std::vector<MaterialReference> parts, std::vector<std::uint32_t> element_parts)
    : parts_(std::move(parts)), element_parts_(std::move(element_parts)) {
    if (parts_.empty() || !parts_[0].name.empty())
        throw std::invalid_argument("part 0 of a blob group is the object's material and has no name");
    for (const std::uint32_t part : element_parts_)
        if (part >= parts_.size()) throw std::invalid_argument("element part " + std::to_string(part) + " out of range");
}

MaterialBlend BlobMaterials::blend(const BlobGroup& group, std::span<const std::uint32_t> listed,
                                   const Vec3d& point) const {
    // Each touched part's summed terms. A point meets few parts, so a list searched in order beats a table indexed
    // by part, which would have to be cleared or kept per thread.
    InlineVector<Share, 16> sums;
    group.for_each_term(listed, point, [&](std::uint32_t element, double term) {
        const std::uint32_t part = element_parts_[element];
        Share* found = std::find_if(sums.begin(), sums.end(), [&](const Share& s) { return s.part == part; });
        if (found == sums.end()) found = &sums.emplace_back(Share{part, 0.0});
        found->value += term_of(group.elements()[element], point, term);
    });
    InlineVector<Share, 16> shares;  // the positive ones
    for (const Share& sum : sums)
        if (sum.value > 0) shares.emplace_back(sum);

    MaterialBlend blend;
    if (shares.empty()) {  // rounding at the edge of the supports: the nearest element's part
        double nearest = std::numeric_limits<double>::infinity();
        blend.count = 1;
        blend.weight[0] = 1;
        group.for_each_term(listed, point, [&](std::uint32_t element, double) {
            const double distance = group.elements()[element].distance_squared(point);
            if (distance < nearest) {
                nearest = distance;
                blend.part[0] = element_parts_[element];
            }
        });
        return blend;
    }
    const std::size_t kept = std::min<std::size_t>(shares.size(), MaterialBlend::kMaxParts);
    std::partial_sort(shares.begin(), shares.begin() + std::ptrdiff_t(kept), shares.end(),
                      [](const Share& a, const Share& b) { return a.value > b.value || (a.value == b.value && a.part < b.part); });
    double total = 0;
    for (std::size_t i = 0; i < kept; ++i) total += shares[i].value;
    // The largest share is at least a quarter, so it can take the others' rounding and stays positive.
    std::int64_t others = 0;
    std::array<std::int64_t, MaterialBlend::kMaxParts> units{};
    for (std::size_t i = 1; i < kept; ++i) {
        units[i] = std::llround(shares[i].value / total * double(kWeightUnits));
        others += units[i];
    }
    units[0] = kWeightUnits - others;
    for (std::size_t i = 0; i < kept; ++i) {
        if (units[i] == 0) continue;
        blend.part[std::size_t(blend.count)] = shares[i].part;
        blend.weight[std::size_t(blend.count)] = float(double(units[i]) / double(kWeightUnits));
        ++blend.count;
    }
    return blend;
}

}  // namespace isotrace
