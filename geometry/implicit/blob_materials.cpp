#include "geometry/implicit/blob_materials.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace isotrace {
namespace {

constexpr double kHardCubeReach = 1e-5;        // see the header: the face of a hard cube, within rounding
constexpr std::int64_t kWeightUnits = 1 << 20;  // the weights' resolution: sums of these stay exact in float

struct Share {
    std::uint32_t part;
    double value;
};

// Each part's summed terms, indexed by part, the parts touched (to clear them for the next point), and their
// positive shares: per thread, kept from point to point.
struct PartSums {
    std::vector<double> sum;
    std::vector<std::uint32_t> touched;
    std::vector<bool> listed;
    std::vector<Share> shares;
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
    thread_local PartSums sums;
    if (sums.sum.size() < parts_.size()) {
        sums.sum.resize(parts_.size(), 0.0);
        sums.listed.resize(parts_.size(), false);
    }
    group.for_each_term(listed, point, [&](std::uint32_t element, double term) {
        const std::uint32_t part = element_parts_[element];
        if (!sums.listed[part]) {
            sums.listed[part] = true;
            sums.touched.push_back(part);
        }
        sums.sum[part] += term_of(group.elements()[element], point, term);
    });
    std::vector<Share>& shares = sums.shares;
    shares.clear();
    for (const std::uint32_t part : sums.touched) {
        if (sums.sum[part] > 0) shares.push_back({part, sums.sum[part]});
        sums.sum[part] = 0;
        sums.listed[part] = false;
    }
    sums.touched.clear();

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
