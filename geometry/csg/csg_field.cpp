// The implicit field of a CSG tree: min for union, max for intersection, max(f₀, −f₁, …) for difference, each
// with the gradient of the operand that attains it (negated for a subtracted one), so Hermite data at a crossing
// are those of the leaf surface that bounds the result there — sharp edges keep their two normals.
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "geometry/csg/csg_shape.h"
#include "geometry/field/transformed_field.h"

namespace isotrace {
namespace {

class CsgField final : public ImplicitField {
public:
    explicit CsgField(const CsgShape& csg) : operation_(csg.operation()) {
        for (std::size_t i = 0; i < csg.operand_count(); ++i) {
            std::unique_ptr<ImplicitField> field = csg.operand(i).implicit_field();
            if (!field)
                throw std::invalid_argument("children[" + std::to_string(i) + "]: a \"" + csg.operand(i).type_name() +
                                            "\" has no implicit field");
            if (const auto& placement = csg.operand_placement(i)) field = transformed_field(std::move(field), *placement);
            operands_.push_back(std::move(field));
        }
    }

    double value(const Vec3d& p) const override { return signed_value(p, deciding_operand(p)); }
    Vec3d gradient(const Vec3d& p) const override {
        const std::size_t i = deciding_operand(p);
        const Vec3d g = operands_[i]->gradient(p);
        return negated(i) ? -g : g;
    }
    FieldBox bounds() const override {
        FieldBox box = operands_[0]->bounds();
        if (operation_ == CsgOperation::Difference) return box;
        for (std::size_t i = 1; i < operands_.size(); ++i) {
            const FieldBox other = operands_[i]->bounds();
            if (operation_ == CsgOperation::Union) {
                box.extend(other);
            } else {
                box.lower = max(box.lower, other.lower);
                box.upper = min(box.upper, other.upper);
            }
        }
        box.upper = max(box.upper, box.lower);  // disjoint operands of an intersection: an empty box
        return box;
    }
    // The boundary of a combination lies on the operands' boundaries.
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        return std::any_of(operands_.begin(), operands_.end(),
                           [&](const auto& field) { return field->may_reach_surface(centre, radius); });
    }

private:
    bool negated(std::size_t i) const { return operation_ == CsgOperation::Difference && i > 0; }
    double signed_value(const Vec3d& p, std::size_t i) const {
        const double v = operands_[i]->value(p);
        return negated(i) ? -v : v;
    }
    // The operand whose (signed) value is the combination's: the smallest for union, else the largest.
    std::size_t deciding_operand(const Vec3d& p) const {
        std::size_t best = 0;
        double best_value = signed_value(p, 0);
        for (std::size_t i = 1; i < operands_.size(); ++i) {
            const double v = signed_value(p, i);
            if (operation_ == CsgOperation::Union ? v < best_value : v > best_value) {
                best = i;
                best_value = v;
            }
        }
        return best;
    }

    CsgOperation operation_;
    std::vector<std::unique_ptr<ImplicitField>> operands_;
};

}  // namespace

std::unique_ptr<ImplicitField> CsgShape::implicit_field() const { return std::make_unique<CsgField>(*this); }

}  // namespace isotrace
