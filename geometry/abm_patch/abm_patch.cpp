#include "geometry/abm_patch/abm_patch.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/abm_patch/loop_check.h"

namespace isotrace {
namespace {

constexpr int kMaxSides = PatchDomain::kMaxSides;

// d_i^p of every side and its gradient, with the distances divided by the largest one: the weights are
// homogeneous of one degree in the distances, so F does not change, and the products cannot underflow away
// from the corners.
struct DistancePowers {
    double value[kMaxSides], dx[kMaxSides], dy[kMaxSides];
};

DistancePowers distance_powers(const Footprint* footprints, int n, double exponent) {
    double largest = 0;
    for (int i = 0; i < n; ++i) largest = std::max(largest, footprints[i].distance);
    DistancePowers powers;
    for (int i = 0; i < n; ++i) {
        const double r = largest > 0 ? footprints[i].distance / largest : 0;
        const double slope = exponent == 1 ? 1 : exponent * std::pow(r, exponent - 1);
        powers.value[i] = exponent == 1 ? r : std::pow(r, exponent);
        powers.dx[i] = largest > 0 ? slope * footprints[i].distance_dx / largest : 0;
        powers.dy[i] = largest > 0 ? slope * footprints[i].distance_dy / largest : 0;
    }
    return powers;
}

// Product of value[j] over j ≠ skip (and j ≠ also_skip).
double product_except(const double* value, int n, int skip, int also_skip = -1) {
    double product = 1;
    for (int j = 0; j < n; ++j)
        if (j != skip && j != also_skip) product *= value[j];
    return product;
}

}  // namespace

AbmPatch::AbmPatch(std::shared_ptr<const PatchDomain> domain, std::vector<PatchSide> sides, double exponent,
                   double closure_tolerance)
    : domain_(std::move(domain)), sides_(std::move(sides)), exponent_(exponent) {
    if (int(sides_.size()) != domain_->sides())
        throw std::invalid_argument("the " + domain_->name() + " domain has " + std::to_string(domain_->sides()) +
                                    " sides, but the patch has " + std::to_string(sides_.size()) + " curves");
    if (!(exponent_ >= kMinExponent && exponent_ <= kMaxExponent))
        throw std::invalid_argument("p: the weight exponent must be in [1, 8], got " + std::to_string(exponent_));
    check_not_degenerate(sides_);
    check_closed_loop(sides_, closure_tolerance);
    check_not_self_crossing(sides_);
}

AbmPatch AbmPatch::with_sides(std::vector<PatchSide> sides) const {
    if (sides.size() != sides_.size()) throw std::invalid_argument("with_sides: the patch has " + std::to_string(sides_.size()) + " sides");
    AbmPatch patch = *this;
    patch.sides_ = std::move(sides);
    return patch;
}

Vec3d AbmPatch::operator()(DomainPoint x) const { return evaluate(x, nullptr); }

PatchJet AbmPatch::jet(DomainPoint x) const {
    PatchJet jet;
    jet.point = evaluate(x, &jet);
    return jet;
}

Vec3d AbmPatch::evaluate(DomainPoint x, PatchJet* jet) const {
    const int n = domain_->sides();
    Footprint footprints[kMaxSides];
    domain_->footprints(x, footprints);
    const DistancePowers powers = distance_powers(footprints, n, exponent_);
    double weight[kMaxSides], total = 0;
    for (int i = 0; i < n; ++i) total += weight[i] = product_except(powers.value, n, i);

    if (!(total > 0)) {  // a corner: the two adjacent sides nearest to x meet there
        int side = 0;
        for (int i = 1; i < n; ++i)
            if (footprints[i].distance + footprints[(i + 1) % n].distance <
                footprints[side].distance + footprints[(side + 1) % n].distance)
                side = i;
        if (jet) jet->dx = jet->dy = Vec3d{};
        return sides_[std::size_t(side)].end();
    }

    // Attribute i is c_i(s_i), plus d_i·r_i(s_i) where the side has a cross-boundary tangent r_i (with the true
    // domain distance: r is per unit of it); tangent[i] is its derivative in s_i, ribbon[i] the one in d_i.
    Vec3d attribute[kMaxSides], tangent[kMaxSides], ribbon[kMaxSides];
    Vec3d sum{};
    for (int i = 0; i < n; ++i) {
        const PatchSide& side = sides_[std::size_t(i)];
        const double s = footprints[i].parameter, d = footprints[i].distance;
        if (jet) {
            const auto [point, derivative] = side.point_and_tangent(s);
            attribute[i] = point;
            tangent[i] = derivative;
            ribbon[i] = Vec3d{};
            if (side.ribbon) {
                const auto [r, dr] = side.ribbon->value_and_derivative(s);
                attribute[i] = attribute[i] + d * r;
                tangent[i] = tangent[i] + d * dr;
                ribbon[i] = r;
            }
        } else if (weight[i] > 0) {
            attribute[i] = side.point(s);
            if (side.ribbon) attribute[i] = attribute[i] + d * (*side.ribbon)(s);
        }
        if (weight[i] > 0) sum = sum + weight[i] * attribute[i];
    }
    const Vec3d value = (1 / total) * sum;
    if (!jet) return value;

    // ∇F = Σ_i [∇W_i (f_i − F) + W_i (f_i′ ∇s_i + r_i ∇d_i)] / Σ W, with ∇W_i = Σ_{k≠i} ∇(d_k^p) Π_{j≠i,k} d_j^p.
    Vec3d dx{}, dy{};
    for (int i = 0; i < n; ++i) {
        double weight_dx = 0, weight_dy = 0;
        for (int k = 0; k < n; ++k) {
            if (k == i) continue;
            const double others = product_except(powers.value, n, i, k);
            weight_dx += powers.dx[k] * others;
            weight_dy += powers.dy[k] * others;
        }
        const Vec3d offset = attribute[i] - value;
        dx = dx + weight_dx * offset + (weight[i] * footprints[i].parameter_dx) * tangent[i] +
             (weight[i] * footprints[i].distance_dx) * ribbon[i];
        dy = dy + weight_dy * offset + (weight[i] * footprints[i].parameter_dy) * tangent[i] +
             (weight[i] * footprints[i].distance_dy) * ribbon[i];
    }
    jet->dx = (1 / total) * dx;
    jet->dy = (1 / total) * dy;
    return value;
}

Vec3d AbmPatch::normal(DomainPoint x) const {
    const PatchJet j = jet(x);
    const Vec3d n = domain_->orientation() * cross(j.dx, j.dy);
    const double len = length(n);
    return len > 0 && std::isfinite(len) ? n / len : Vec3d{};
}

Vec3d AbmPatch::unit_or_inside(const Vec3d& n, double scale, DomainPoint x) const {
    const double len = length(n);
    if (len > 1e-12 * scale && std::isfinite(len)) return n / len;
    const DomainPoint centre = domain_->centre();
    const double step = 1e-6;
    return normal({x.x + step * (centre.x - x.x), x.y + step * (centre.y - x.y)});
}

Vec3d AbmPatch::side_normal(int side, double t) const {
    const int n = domain_->sides();
    const DomainPoint x = domain_->on_side(side, t);
    Footprint footprints[kMaxSides];
    domain_->footprints(x, footprints);
    footprints[side].distance = 0;  // exactly on the side, whatever the rounding of x
    const DistancePowers powers = distance_powers(footprints, n, exponent_);
    const auto [point, tangent] = sides_[std::size_t(side)].point_and_tangent(t);
    if (const auto& ribbon = sides_[std::size_t(side)].ribbon) {  // p > 1: the patch leaves the side along r
        const Vec3d r = (*ribbon)(t);
        return unit_or_inside(cross(tangent, r), length(tangent) * length(r), x);
    }
    Vec3d away{};
    for (int j = 0; j < n; ++j)
        if (j != side)
            away = away + product_except(powers.value, n, side, j) *
                              (sides_[std::size_t(j)].point(footprints[j].parameter) - point);
    return unit_or_inside(cross(tangent, away), length(tangent) * length(away), x);
}

Vec3d AbmPatch::corner_normal(int corner) const {
    return unit_or_inside(Vec3d{}, 1, domain_->corners()[std::size_t(corner)]);
}

}  // namespace isotrace
