#pragma once
// The quadratic error function of dual contouring (Ju et al. 2002): Q(x) = Σ (nᵢ·(x − pᵢ))² over a cell's
// Hermite data (crossing pᵢ, unit normal nᵢ). Minimised about the mass point m (the mean of the pᵢ) by a truncated
// eigen-decomposition of AᵀA: directions whose singular value is below `kTruncation` × the largest are left at
// m, so a flat or cylindrical patch gets a stable vertex on it and a corner the planes' intersection.
#include "renderer/math/vec3.h"

namespace isotrace {

class Qef {
public:
    static constexpr double kTruncation = 0.1;

    // A plane through p with normal n (n need not be unit: it is normalised; a zero n adds only to the mass point).
    void add(const Vec3d& p, const Vec3d& n);
    bool empty() const { return count_ == 0; }
    Vec3d mass_point() const { return point_sum_ / double(count_); }
    // The minimiser (pseudo-inverse, truncated), near the mass point.
    Vec3d solve() const;

private:
    double ata_[6] = {};  // xx, xy, xz, yy, yz, zz
    Vec3d atb_;           // Σ n (n·p), with p relative to the first point (for precision)
    Vec3d reference_;     // the first point
    Vec3d point_sum_;     // relative to reference_
    int count_ = 0;
};

}  // namespace isotrace
