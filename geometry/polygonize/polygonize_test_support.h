#pragma once
// Analytic signed-distance fields with known surfaces, for the polygonisers' tests.
#include <algorithm>
#include <cmath>

#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/plugin/implicit_field.h"

namespace isotrace {

// A field whose may_reach_surface trusts |f| as the distance (exact for the signed distances below).
class DistanceFieldForTests : public ImplicitField {
public:
    bool may_reach_surface(const Vec3d& centre, double radius) const override {
        return std::abs(value(centre)) <= radius;
    }
};

class BallField final : public DistanceFieldForTests {
public:
    BallField(const Vec3d& centre, double radius) : centre_(centre), radius_(radius) {}
    double value(const Vec3d& p) const override { return length(p - centre_) - radius_; }
    Vec3d gradient(const Vec3d& p) const override { return normalize(p - centre_); }
    FieldBox bounds() const override { return {centre_ - Vec3d{1, 1, 1} * radius_, centre_ + Vec3d{1, 1, 1} * radius_}; }

private:
    Vec3d centre_;
    double radius_;
};

// The torus about the z axis through `centre`: ring radius R, tube radius r.
class TorusField final : public DistanceFieldForTests {
public:
    TorusField(const Vec3d& centre, double ring, double tube) : centre_(centre), ring_(ring), tube_(tube) {}
    double value(const Vec3d& p) const override {
        const Vec3d d = p - centre_;
        return std::hypot(std::hypot(d.x, d.y) - ring_, d.z) - tube_;
    }
    Vec3d gradient(const Vec3d& p) const override {
        const Vec3d d = p - centre_;
        const double rho = std::hypot(d.x, d.y);
        const Vec3d ring_point = Vec3d(d.x / rho, d.y / rho, 0) * ring_;
        return normalize(d - ring_point);
    }
    FieldBox bounds() const override {
        const Vec3d half(ring_ + tube_, ring_ + tube_, tube_);
        return {centre_ - half, centre_ + half};
    }

private:
    Vec3d centre_;
    double ring_, tube_;
};

// The solid half ball |p| ≤ 1, z ≥ 0: its enclosing sphere's centre, the origin, lies on its flat face.
class HalfBallField final : public DistanceFieldForTests {
public:
    double value(const Vec3d& p) const override { return std::max(length(p) - 1, -p.z); }
    Vec3d gradient(const Vec3d& p) const override {
        return length(p) - 1 > -p.z ? normalize(p) : Vec3d{0, 0, -1};
    }
    FieldBox bounds() const override { return {{-1, -1, 0}, {1, 1, 1}}; }
    // max() of two distances is not a distance: |f| still bounds it from below (each part is 1-Lipschitz).
};

// |f|/|∇f| (the first-order distance to the surface) at every triangle's centroid: the largest. (Vertices alone
// say little for marching cubes, whose vertices are roots.)
inline double worst_centroid_error(const ImplicitField& field, const TriangleMeshData& mesh) {
    double worst = 0;
    for (const auto& t : mesh.triangles) {
        const Vec3d c = (Vec3d(mesh.positions[t[0]]) + Vec3d(mesh.positions[t[1]]) + Vec3d(mesh.positions[t[2]])) / 3.0;
        worst = std::max(worst, std::abs(field.value(c)) / length(field.gradient(c)));
    }
    return worst;
}

}  // namespace isotrace
