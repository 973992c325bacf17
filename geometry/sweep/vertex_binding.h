#pragma once
// Binding a point to a sweep's cross-sections (the paper's §4.1, two steps). Step 1: the section parameter t
// with ⟨v − C(t), N(t)⟩ = 0 (eq. 5). Several sections may pass through v; every sign change of the left-hand
// side on a fine sampling of [0, 1] is refined (Illinois regula falsi) and one root is chosen deterministically:
//   1. a section that contains v (d ≤ 0) before one that does not,
//   2. then the smallest |d| (the nearest sweep surface),
//   3. then the smallest t.
// A point that no section plane passes through within [0, 1] (beyond the sweep's ends), or that only touches
// one without crossing it, is not bound; a point on an end plane (within kEndPlaneTolerance) is bound to it. Step 2: v̂ = R(t)ᵀ(v − C(t)) (eq. 6), θ = atan2(v̂_y, v̂_x) of the local
// coordinates (the paper prints tan⁻¹ of global ones) and d = |v̂| − r(θ, t) (eq. 7), |v̂| measured in the
// section plane (v̂_z is zero at the root up to the refinement tolerance).
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/math/quaternion.h"
#include "renderer/math/vec3.h"

namespace isotrace {

class SweepSurface;

struct VertexBinding {
    double theta = 0;  // (−π, π]
    double t = 0;      // [0, 1]
    double d = 0;      // signed distance from the surface within the section, < 0 inside
    double radius = 0; // r(θ, t) when bound (0: unknown, eq. (8) as printed for every point)
};

// Eq. (8) with θ_i: C(t) + R(t)·(ρ·cos θ, ρ·sin θ, 0) on any (edited) sweep, ρ = r(θ,t) + d outside the sweep.
// Inside it (d < 0, radius known) ρ = r(θ,t)·(radius + d)/radius: the point keeps its share of the section's
// radius, as printed it would keep its depth below the surface, so that a widened section tears points near its
// axis apart by the whole widening (a thin part through the axis splits) and a narrowed one folds them over it.
Vec3d bound_position(const SweepSurface& sweep, const VertexBinding& binding);

// Samples C and N once per sweep so that binding many vertices only refines the brackets.
class SweepBinder {
public:
    static constexpr int kSamplesPerKey = 64;
    // Points within this fraction of the sweep's size of an end section's plane lie on it.
    static constexpr double kEndPlaneTolerance = 1e-9;

    // `samples_per_key` samples of t per key interval (≥ 2, at most 4096).
    explicit SweepBinder(const SweepSurface& sweep, int samples_per_key = kSamplesPerKey);

    // The samples of t for a sweep of `keys` key sections: the sign tests each bound point costs.
    static std::uint64_t sample_count(std::size_t keys, int samples_per_key = kSamplesPerKey) {
        return std::uint64_t(samples_per_key) * (std::max<std::size_t>(keys, 1) - 1) + 1;
    }

    std::optional<VertexBinding> bind(const Vec3d& v) const;
    // Every root of eq. (5) in [0, 1] with its binding, in increasing t (for tests and diagnostics).
    std::vector<VertexBinding> all_roots(const Vec3d& v) const;

private:
    double plane_distance(const Vec3d& v, double t) const;
    VertexBinding binding_at(const Vec3d& v, double t) const;

    const SweepSurface& sweep_;
    std::vector<double> t_;
    std::vector<Vec3d> centre_, normal_;
};

}  // namespace isotrace
