// The implicit field of a blob group for the polygonisers: f = T − Σ wᵢ·fᵢ (negative inside), gradient −∇Σ.
//
// may_reach_surface bounds the sum over the ball by Lipschitz constants: element i changes by at most
// |wᵢ|·2·|f'(0)|/Rᵢ per unit length (f is non-increasing and convex in r², so |df/dr²| ≤ |f'(0)|/R², and
// |∇dist²| = 2·dist ≤ 2R inside the support). Elements whose support misses the ball contribute nothing there.
#include <cmath>

#include "geometry/field/box_index.h"
#include "geometry/implicit/blob_group_shape.h"

namespace isotrace {
namespace {

std::vector<FieldBox> support_boxes(const BlobGroup& group) {
    std::vector<FieldBox> boxes;
    for (const Metacube& element : group.elements()) {
        const WorldBounds b = element.support_bounds();
        boxes.push_back({b.lower, b.upper});
    }
    return boxes;
}

class BlobGroupField final : public ImplicitField {
public:
    explicit BlobGroupField(const BlobGroup& group)
        : group_(group), supports_boxes_(support_boxes(group)), supports_(supports_boxes_) {
        for (const Metacube& element : group.elements())
            slopes_.push_back(element.is_hard_cube()
                                  ? INFINITY
                                  : std::abs(element.weight()) * 2 * std::abs(group.kernel().unit_derivative(0)) /
                                        element.radius());
        for (const FieldBox& support : supports_boxes_) bounds_.extend(support);
    }

    double value(const Vec3d& p) const override { return group_.threshold() - group_.field(p); }
    Vec3d gradient(const Vec3d& p) const override { return -group_.gradient(p); }
    FieldBox bounds() const override { return bounds_; }
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        double slope = 0;
        bool any = false;
        supports_.for_each_near(centre, radius, [&](std::uint32_t i) {
            any = true;
            slope += slopes_[i];
            return std::isfinite(slope);  // a hard cube's step: no bound, stop looking
        });
        if (!any) return false;  // the field is 0 < T all over the ball
        return !(std::abs(value(centre)) > slope * radius);
    }

private:
    const BlobGroup& group_;
    std::vector<FieldBox> supports_boxes_;
    BoxIndex supports_;
    std::vector<double> slopes_;  // per element, the Lipschitz constant of wᵢ·fᵢ (infinite for hard cubes)
    FieldBox bounds_ = FieldBox::none();
};

}  // namespace

std::unique_ptr<ImplicitField> BlobGroupShape::implicit_field() const { return std::make_unique<BlobGroupField>(group()); }

}  // namespace isotrace
