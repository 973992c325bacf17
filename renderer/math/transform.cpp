#include "renderer/math/transform.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace isotrace {
namespace {

using Matrix = Transform::Matrix;

Matrix identity_matrix() {
    Matrix m{};
    for (int i = 0; i < 4; ++i) m[i][i] = 1;
    return m;
}

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

// Gauss-Jordan with partial pivoting; false when singular.
bool invert(const Matrix& m, Matrix& inverse) {
    Matrix a = m;
    inverse = identity_matrix();
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int row = col + 1; row < 4; ++row)
            if (std::abs(a[row][col]) > std::abs(a[pivot][col])) pivot = row;
        if (!(std::abs(a[pivot][col]) > 1e-300)) return false;
        std::swap(a[col], a[pivot]);
        std::swap(inverse[col], inverse[pivot]);
        const double scale = 1.0 / a[col][col];
        for (int j = 0; j < 4; ++j) {
            a[col][j] *= scale;
            inverse[col][j] *= scale;
        }
        for (int row = 0; row < 4; ++row) {
            if (row == col) continue;
            const double f = a[row][col];
            if (f == 0) continue;
            for (int j = 0; j < 4; ++j) {
                a[row][j] -= f * a[col][j];
                inverse[row][j] -= f * inverse[col][j];
            }
        }
    }
    return true;
}

// Scaled by the largest entry so that entries of 1e-200 or 1e200 neither underflow nor overflow when squared.
double frobenius_norm_3x3(const Matrix& m) {
    double largest = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) largest = std::max(largest, std::abs(m[i][j]));
    if (!(largest > 0) || !std::isfinite(largest)) return largest;
    double sum = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) sum += (m[i][j] / largest) * (m[i][j] / largest);
    return largest * std::sqrt(sum);
}

}  // namespace

Transform::Transform() : m_(identity_matrix()), inv_(identity_matrix()) {}

Transform Transform::from_matrix(const Matrix& m) {
    for (const auto& row : m)
        for (double v : row)
            if (!std::isfinite(v)) throw std::invalid_argument("matrix has a non-finite entry");
    if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1)
        throw std::invalid_argument("matrix is not affine: the last row must be [0, 0, 0, 1]");
    Matrix inv;
    if (!invert(m, inv)) throw std::invalid_argument("matrix is singular");
    const Transform t(m, inv);
    // Singular relative to the size of the columns (Hadamard's bound), so that a regular matrix of small
    // scale (units of micrometres: determinant 1e-18) is accepted and a nearly flat one of any scale is not.
    double column_lengths = 1;
    for (int j = 0; j < 3; ++j) column_lengths *= length(Vec3d(m[0][j], m[1][j], m[2][j]));
    if (!(std::abs(t.determinant()) > 1e-12 * column_lengths)) throw std::invalid_argument("matrix is singular");
    return t;
}

Transform Transform::inverse_of_accepted(const Matrix& m) {
    Matrix inv;
    invert(m, inv);
    return {inv, m};
}

Transform Transform::translate(const Vec3d& o) {
    Matrix m = identity_matrix(), inv = identity_matrix();
    for (int i = 0; i < 3; ++i) {
        m[i][3] = o[i];
        inv[i][3] = -o[i];
    }
    return {m, inv};
}

Transform Transform::scale(const Vec3d& s) {
    if (s.x == 0 || s.y == 0 || s.z == 0) throw std::invalid_argument("scale factor is zero");
    Matrix m = identity_matrix(), inv = identity_matrix();
    for (int i = 0; i < 3; ++i) {
        m[i][i] = s[i];
        inv[i][i] = 1.0 / s[i];
    }
    return {m, inv};
}

Transform Transform::rotate(const Vec3d& axis, double degrees) {
    const double len = length(axis);
    if (!(len > 0)) throw std::invalid_argument("rotation axis is zero");
    const Vec3d a = axis / len;
    const double theta = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(theta), s = std::sin(theta), t = 1 - c;
    Matrix m = identity_matrix();
    m[0] = {t * a.x * a.x + c, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y, 0};
    m[1] = {t * a.x * a.y + s * a.z, t * a.y * a.y + c, t * a.y * a.z - s * a.x, 0};
    m[2] = {t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, t * a.z * a.z + c, 0};
    Matrix inv = identity_matrix();  // rotation: inverse = transpose
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) inv[i][j] = m[j][i];
    return {m, inv};
}

Transform Transform::look_at(const Vec3d& eye, const Vec3d& target, const Vec3d& up) {
    const Vec3d forward = target - eye;
    if (!(length(forward) > 0)) throw std::invalid_argument("eye and target coincide");
    const Vec3d back = normalize(-forward);  // camera +z points away from the view direction
    const Vec3d side = cross(up, back);
    if (!(length(side) > 1e-12 * length(up))) throw std::invalid_argument("up is parallel to the view direction");
    const Vec3d right = normalize(side);
    const Vec3d true_up = cross(back, right);
    Matrix m = identity_matrix();
    for (int i = 0; i < 3; ++i) {
        m[i][0] = right[i];
        m[i][1] = true_up[i];
        m[i][2] = back[i];
        m[i][3] = eye[i];
    }
    return from_matrix(m);
}

Transform Transform::inverse() const { return {inv_, m_}; }

Transform Transform::operator*(const Transform& rhs) const {
    return {multiply(m_, rhs.m_), multiply(rhs.inv_, inv_)};
}

bool Transform::is_identity() const { return m_ == identity_matrix(); }

double Transform::determinant() const {
    return m_[0][0] * (m_[1][1] * m_[2][2] - m_[1][2] * m_[2][1]) -
           m_[0][1] * (m_[1][0] * m_[2][2] - m_[1][2] * m_[2][0]) +
           m_[0][2] * (m_[1][0] * m_[2][1] - m_[1][1] * m_[2][0]);
}

double Transform::similarity_scale(double tolerance) const {
    // Columns of the linear part must be orthogonal and of equal length.
    Vec3d columns[3];
    for (int j = 0; j < 3; ++j) columns[j] = {m_[0][j], m_[1][j], m_[2][j]};
    const double s2 = dot(columns[0], columns[0]);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double expected = i == j ? s2 : 0.0;
            if (std::abs(dot(columns[i], columns[j]) - expected) > tolerance * s2) return 0;
        }
    return std::sqrt(s2);
}

double Transform::linear_norm() const { return frobenius_norm_3x3(m_); }

double Transform::inverse_linear_norm() const { return frobenius_norm_3x3(inv_); }

double Transform::condition_number() const { return linear_norm() * inverse_linear_norm(); }

}  // namespace isotrace
