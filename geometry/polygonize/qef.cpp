#include "geometry/polygonize/qef.h"

#include <algorithm>
#include <cmath>

namespace isotrace {
namespace {

using Matrix3 = double[3][3];

// Eigen-decomposition of a symmetric 3×3 matrix by cyclic Jacobi rotations: a = v·diag(eigen)·vᵀ.
void symmetric_eigen(Matrix3 a, Matrix3 v, double eigen[3]) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) v[i][j] = i == j;
    for (int sweep = 0; sweep < 16; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off <= 1e-30 * (a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2]) || off == 0) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                const double t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
                const double c = 1 / std::sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 3; ++k) {  // a ← Jᵀ a J
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {  // v ← v J
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    for (int i = 0; i < 3; ++i) eigen[i] = a[i][i];
}

}  // namespace

void Qef::add(const Vec3d& p, const Vec3d& n) {
    if (count_ == 0) reference_ = p;
    const Vec3d q = p - reference_;
    point_sum_ += q;
    ++count_;
    const double l = length(n);
    if (!(l > 0) || !std::isfinite(l)) return;
    const Vec3d u = n / l;
    ata_[0] += u.x * u.x;
    ata_[1] += u.x * u.y;
    ata_[2] += u.x * u.z;
    ata_[3] += u.y * u.y;
    ata_[4] += u.y * u.z;
    ata_[5] += u.z * u.z;
    const double d = dot(u, q);
    atb_ += u * d;
    btb_ += d * d;
}

void Qef::merge(const Qef& other) {
    if (other.count_ == 0) return;
    if (count_ == 0) {
        *this = other;
        return;
    }
    // Move the other's planes to this reference: with δ = reference_ − other.reference_, each d = n·p becomes
    // d − n·δ, so Aᵀb loses AᵀA·δ and bᵀb becomes Σ (d − n·δ)².
    const Vec3d delta = reference_ - other.reference_;
    const double* m = other.ata_;
    const Vec3d ata_delta(m[0] * delta.x + m[1] * delta.y + m[2] * delta.z, m[1] * delta.x + m[3] * delta.y + m[4] * delta.z,
                          m[2] * delta.x + m[4] * delta.y + m[5] * delta.z);
    for (int i = 0; i < 6; ++i) ata_[i] += m[i];
    atb_ += other.atb_ - ata_delta;
    btb_ += other.btb_ - 2 * dot(delta, other.atb_) + dot(delta, ata_delta);
    point_sum_ += other.point_sum_ - delta * double(other.count_);
    count_ += other.count_;
}

double Qef::error(const Vec3d& x) const {
    // xᵀAᵀAx − 2xᵀAᵀb + bᵀb with x relative to the reference; never below zero (rounding).
    const Vec3d y = x - reference_;
    const Vec3d ata_y(ata_[0] * y.x + ata_[1] * y.y + ata_[2] * y.z, ata_[1] * y.x + ata_[3] * y.y + ata_[4] * y.z,
                      ata_[2] * y.x + ata_[4] * y.y + ata_[5] * y.z);
    return std::max(0.0, dot(y, ata_y) - 2 * dot(y, atb_) + btb_);
}

Vec3d Qef::solve() const {
    const Vec3d mass = point_sum_ / double(count_);
    // Solve AᵀA·y = Aᵀb − AᵀA·m for y = x − m.
    const double m[3][3] = {{ata_[0], ata_[1], ata_[2]}, {ata_[1], ata_[3], ata_[4]}, {ata_[2], ata_[4], ata_[5]}};
    Vec3d rhs = atb_;
    for (int i = 0; i < 3; ++i) rhs[i] -= m[i][0] * mass.x + m[i][1] * mass.y + m[i][2] * mass.z;
    Matrix3 a, v;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a[i][j] = m[i][j];
    double eigen[3];
    symmetric_eigen(a, v, eigen);
    const double largest = std::max({std::abs(eigen[0]), std::abs(eigen[1]), std::abs(eigen[2])});
    // Singular values of A are the square roots of AᵀA's eigenvalues: truncate at kTruncation² of the largest.
    const double cut = kTruncation * kTruncation * largest;
    Vec3d y;
    for (int k = 0; k < 3; ++k) {
        if (!(eigen[k] > cut) || eigen[k] <= 0) continue;
        const Vec3d axis(v[0][k], v[1][k], v[2][k]);
        y += axis * (dot(axis, rhs) / eigen[k]);
    }
    return reference_ + mass + y;
}

}  // namespace isotrace
