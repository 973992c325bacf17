#pragma once
// Affine transform as a 4x4 double matrix with its inverse kept alongside (scene input is composed in
// double so that long chains of steps do not drift).
#include <array>

#include "renderer/math/vec3.h"

namespace isotrace {

class Transform {
public:
    using Matrix = std::array<std::array<double, 4>, 4>;  // row-major, column vectors: p' = M p

    Transform();  // identity
    // Throws std::invalid_argument when the matrix is singular or not affine.
    static Transform from_matrix(const Matrix& m);
    // from_matrix(m).inverse() for a matrix from_matrix has accepted before, without checking it again: the same bits
    // for the cost of the inversion alone (a placed copy's to_world, made from its inverse at every hit).
    static Transform inverse_of_accepted(const Matrix& m);
    static Transform translate(const Vec3d& offset);
    static Transform scale(const Vec3d& factors);
    static Transform rotate(const Vec3d& axis, double degrees);
    // Camera-to-world for a camera at `eye` looking at `target` (camera looks down -z, y up).
    static Transform look_at(const Vec3d& eye, const Vec3d& target, const Vec3d& up);

    const Matrix& matrix() const& { return m_; }
    // Of a temporary, a copy: a reference into it would dangle once the statement ends.
    Matrix matrix() const&& { return m_; }
    Transform inverse() const;
    Transform operator*(const Transform& rhs) const;  // (A * B)(p) = A(B(p))

    // Inline: cameras transform every camera ray, and hit completion every hit on an instance.
    Vec3d point(const Vec3d& p) const {
        return {m_[0][0] * p.x + m_[0][1] * p.y + m_[0][2] * p.z + m_[0][3],
                m_[1][0] * p.x + m_[1][1] * p.y + m_[1][2] * p.z + m_[1][3],
                m_[2][0] * p.x + m_[2][1] * p.y + m_[2][2] * p.z + m_[2][3]};
    }
    Vec3d vector(const Vec3d& v) const {
        return {m_[0][0] * v.x + m_[0][1] * v.y + m_[0][2] * v.z, m_[1][0] * v.x + m_[1][1] * v.y + m_[1][2] * v.z,
                m_[2][0] * v.x + m_[2][1] * v.y + m_[2][2] * v.z};
    }
    Vec3d normal(const Vec3d& n) const {  // inverse transpose; not normalised
        return {inv_[0][0] * n.x + inv_[1][0] * n.y + inv_[2][0] * n.z,
                inv_[0][1] * n.x + inv_[1][1] * n.y + inv_[2][1] * n.z,
                inv_[0][2] * n.x + inv_[1][2] * n.y + inv_[2][2] * n.z};
    }
    // The inverse's point(), vector() and normal() without copying the inverse out (textures map every shading point back
    // to object space).
    Vec3d inverse_point(const Vec3d& p) const {
        return {inv_[0][0] * p.x + inv_[0][1] * p.y + inv_[0][2] * p.z + inv_[0][3],
                inv_[1][0] * p.x + inv_[1][1] * p.y + inv_[1][2] * p.z + inv_[1][3],
                inv_[2][0] * p.x + inv_[2][1] * p.y + inv_[2][2] * p.z + inv_[2][3]};
    }
    Vec3d inverse_vector(const Vec3d& v) const {
        return {inv_[0][0] * v.x + inv_[0][1] * v.y + inv_[0][2] * v.z,
                inv_[1][0] * v.x + inv_[1][1] * v.y + inv_[1][2] * v.z,
                inv_[2][0] * v.x + inv_[2][1] * v.y + inv_[2][2] * v.z};
    }
    Vec3d inverse_normal(const Vec3d& n) const {  // transpose of the matrix; not normalised
        return {m_[0][0] * n.x + m_[1][0] * n.y + m_[2][0] * n.z, m_[0][1] * n.x + m_[1][1] * n.y + m_[2][1] * n.z,
                m_[0][2] * n.x + m_[1][2] * n.y + m_[2][2] * n.z};
    }
    Vec3f point(const Vec3f& p) const { return Vec3f(point(Vec3d(p))); }
    Vec3f vector(const Vec3f& v) const { return Vec3f(vector(Vec3d(v))); }
    Vec3f normal(const Vec3f& n) const { return Vec3f(normal(Vec3d(n))); }

    bool is_identity() const;
    // Rotation + uniform scale + translation (angles preserved): returns the scale factor, or 0 if not.
    double similarity_scale(double tolerance = 1e-9) const;
    // Determinant of the linear part (negative = handedness flips).
    double determinant() const;
    // Condition number of the linear part A in the Frobenius norm, |A| |A^-1| (between 1 and 3 times the
    // 2-norm one): how much relative precision a ray loses when it is carried into object space.
    double condition_number() const;
    // Frobenius norms of the linear part and of its inverse: how large and how small the transform makes things.
    double linear_norm() const;
    double inverse_linear_norm() const;

private:
    Transform(const Matrix& m, const Matrix& inv) : m_(m), inv_(inv) {}
    Matrix m_;
    Matrix inv_;
};

}  // namespace isotrace
