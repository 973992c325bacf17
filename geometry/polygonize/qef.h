#pragma once
// The quadratic error function of dual contouring (Ju et al. 2002): Q(x) = Σ (nᵢ·(x − pᵢ))² over a cell's
// Hermite data (crossing pᵢ, unit normal nᵢ). Minimised about the mass point m (the mean of the pᵢ) by a truncated
// eigen-decomposition of AᵀA: directions whose singular value is below `kTruncation` × the largest are left at
// m, so a flat or cylindrical patch gets a stable vertex on it and a corner the planes' intersection.
//
// Kept as AᵀA, Aᵀb, bᵀb and the point sum (relative to a reference point), so the QEFs of an octree node's
// children add up to the node's (octree simplification).
#include "renderer/math/vec3.h"

namespace isotrace {

class Qef {
public:
    static constexpr double kTruncation = 0.1;

    // A plane through p with normal n (n need not be unit: it is normalised; a zero n adds only to the mass point).
    void add(const Vec3d& p, const Vec3d& n);
    // Adds another QEF's planes and points: the QEF of the union of both sets of Hermite data.
    void merge(const Qef& other);
    bool empty() const { return count_ == 0; }
    Vec3d mass_point() const { return reference_ + point_sum_ / double(count_); }
    // The minimiser (pseudo-inverse, truncated), near the mass point.
    Vec3d solve() const;
    // Q(x): the sum of squared distances from x to the planes.
    double error(const Vec3d& x) const;

private:
    double ata_[6] = {};  // xx, xy, xz, yy, yz, zz
    Vec3d atb_;           // Σ n (n·p), with p relative to reference_ (for precision)
    double btb_ = 0;      // Σ (n·p)², p relative to reference_
    Vec3d reference_;     // the first point
    Vec3d point_sum_;     // relative to reference_
    int count_ = 0;
};

}  // namespace isotrace
