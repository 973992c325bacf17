#include "geometry/abm_patch/patch_domain.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace isotrace {

DomainPoint PatchDomain::on_side(int side, double t) const {
    const DomainPoint& a = corners_[std::size_t(side)];
    const DomainPoint& b = corners_[std::size_t((side + 1) % sides())];
    return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

double PatchDomain::orientation() const {
    double twice_area = 0;
    for (int i = 0; i < sides(); ++i) {
        const DomainPoint& a = corners_[std::size_t(i)];
        const DomainPoint& b = corners_[std::size_t((i + 1) % sides())];
        twice_area += a.x * b.y - b.x * a.y;
    }
    return twice_area > 0 ? 1.0 : -1.0;
}

namespace {

class RightTriangleDomain final : public PatchDomain {
public:
    RightTriangleDomain() : PatchDomain({{0, 0}, {0, 1}, {1, 0}}) {}
    std::string name() const override { return "triangle"; }
    DomainPoint centre() const override {
        const double r = 1 - std::numbers::sqrt2 / 2;  // inradius (a + b − c)/2
        return {r, r};
    }
    void footprints(DomainPoint p, Footprint* out) const override {
        const double h = 1 / std::numbers::sqrt2;
        out[0] = {std::max(p.x, 0.0), 1, 0, p.y, 0, 1};
        out[1] = {std::max((1 - p.x - p.y) * h, 0.0), -h, -h, (p.x - p.y + 1) / 2, 0.5, -0.5};
        out[2] = {std::max(p.y, 0.0), 0, 1, 1 - p.x, -1, 0};
    }
};

class UnitSquareDomain final : public PatchDomain {
public:
    UnitSquareDomain() : PatchDomain({{0, 0}, {0, 1}, {1, 1}, {1, 0}}) {}
    std::string name() const override { return "square"; }
    DomainPoint centre() const override { return {0.5, 0.5}; }
    void footprints(DomainPoint p, Footprint* out) const override {
        out[0] = {std::max(p.x, 0.0), 1, 0, p.y, 0, 1};
        out[1] = {std::max(1 - p.y, 0.0), 0, -1, p.x, 1, 0};
        out[2] = {std::max(1 - p.x, 0.0), -1, 0, 1 - p.y, 0, -1};
        out[3] = {std::max(p.y, 0.0), 0, 1, 1 - p.x, -1, 0};
    }
};

std::vector<DomainPoint> regular_polygon(int n) {
    if (n < 3 || n > PatchDomain::kMaxSides)
        throw std::invalid_argument("a patch needs 3 to " + std::to_string(PatchDomain::kMaxSides) +
                                    " boundary curves, got " + std::to_string(n));
    std::vector<DomainPoint> corners;
    for (int k = 0; k < n; ++k) {
        const double angle = -std::numbers::pi / 2 - std::numbers::pi / n + 2 * std::numbers::pi * k / n;
        corners.push_back({std::cos(angle), std::sin(angle)});
    }
    return corners;
}

class RegularPolygonDomain final : public PatchDomain {
public:
    explicit RegularPolygonDomain(int n) : PatchDomain(regular_polygon(n)) {
        for (int i = 0; i < n; ++i) {  // inward unit normals: the side direction turned left (counter-clockwise)
            const DomainPoint a = corners()[std::size_t(i)], b = corners()[std::size_t((i + 1) % n)];
            const double ex = b.x - a.x, ey = b.y - a.y, len = std::hypot(ex, ey);
            inward_[i] = {-ey / len, ex / len};
        }
    }
    std::string name() const override { return "polygon"; }
    DomainPoint centre() const override { return {0, 0}; }
    void footprints(DomainPoint p, Footprint* out) const override {
        const int n = sides();
        for (int i = 0; i < n; ++i) {
            const DomainPoint a = corners()[std::size_t(i)];
            out[i].distance = std::max((p.x - a.x) * inward_[i].x + (p.y - a.y) * inward_[i].y, 0.0);
            out[i].distance_dx = inward_[i].x;
            out[i].distance_dy = inward_[i].y;
        }
        // s_i from the neighbours' distances: linear along side i (by symmetry), always in [0, 1] inside, smooth
        // where the orthogonal projection would leave the side (N ≥ 5). Where both vanish (the opposite corner
        // of a triangle) W_i is zero, so s_i is irrelevant there.
        for (int i = 0; i < n; ++i) {
            const Footprint& before = out[(i + n - 1) % n];
            const Footprint& after = out[(i + 1) % n];
            const double sum = before.distance + after.distance;
            if (!(sum > 0)) {
                out[i].parameter = out[i].parameter_dx = out[i].parameter_dy = 0;
                continue;
            }
            out[i].parameter = before.distance / sum;
            out[i].parameter_dx = (before.distance_dx * after.distance - before.distance * after.distance_dx) / (sum * sum);
            out[i].parameter_dy = (before.distance_dy * after.distance - before.distance * after.distance_dy) / (sum * sum);
        }
    }

private:
    DomainPoint inward_[kMaxSides];
};

}  // namespace

std::unique_ptr<PatchDomain> right_triangle_domain() { return std::make_unique<RightTriangleDomain>(); }
std::unique_ptr<PatchDomain> unit_square_domain() { return std::make_unique<UnitSquareDomain>(); }
std::unique_ptr<PatchDomain> regular_polygon_domain(int sides) { return std::make_unique<RegularPolygonDomain>(sides); }

}  // namespace isotrace
