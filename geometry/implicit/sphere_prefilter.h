#pragma once
// The first test of every listed element of a blob cell: its compact bounding sphere, tested eight at a time in
// float (GCC/clang vector extensions, renderer/math/lanes.h: two SSE registers on baseline x86-64, one AVX register
// in the AVX2 build of the cell queries) against a stretch of the ray (the march's candidates) or against a point
// (the field and normal at a hit). The float tests carry margins far above their rounding, so they never reject a
// sphere that the exact double test would keep; callers run the exact test on the survivors, which keeps every
// result bit-identical to testing each sphere exactly (and the same in either build: each lane is tested alone).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>

#include "geometry/implicit/bounding_sphere.h"
#include "geometry/implicit/metacube.h"
#include "renderer/math/fused_bounds.h"
#include "renderer/math/lanes.h"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace isotrace {

// |x| + |y| + |z| ≥ |p|: scales the float tests' margins without a square root at the head of every query.
inline double magnitude_bound(const Vec3d& p) { return std::abs(p.x) + std::abs(p.y) + std::abs(p.z); }

// kLanes (eight) spheres as lanes: one 16-byte load per sphere, then a 4×4 transpose within each half (the
// shuffles act on 128-bit halves, as AVX's do, so both builds transpose the same way).
struct SphereLanes {
    static_assert(kLanes == 8, "two groups of four spheres");
    FloatLanes x, y, z, radius;

    explicit SphereLanes(const BoundingSphere* const (&s)[kLanes]) {
        // First and fifth sphere side by side, second and sixth, ...: each half then transposes four spheres.
        const FloatLanes ae = join(*s[0], *s[4]), bf = join(*s[1], *s[5]), cg = join(*s[2], *s[6]),
                         dh = join(*s[3], *s[7]);
        const FloatLanes ab_low = __builtin_shufflevector(ae, bf, 0, 8, 1, 9, 4, 12, 5, 13);
        const FloatLanes cd_low = __builtin_shufflevector(cg, dh, 0, 8, 1, 9, 4, 12, 5, 13);
        const FloatLanes ab_high = __builtin_shufflevector(ae, bf, 2, 10, 3, 11, 6, 14, 7, 15);
        const FloatLanes cd_high = __builtin_shufflevector(cg, dh, 2, 10, 3, 11, 6, 14, 7, 15);
        x = __builtin_shufflevector(ab_low, cd_low, 0, 1, 8, 9, 4, 5, 12, 13);
        y = __builtin_shufflevector(ab_low, cd_low, 2, 3, 10, 11, 6, 7, 14, 15);
        z = __builtin_shufflevector(ab_high, cd_high, 0, 1, 8, 9, 4, 5, 12, 13);
        radius = __builtin_shufflevector(ab_high, cd_high, 2, 3, 10, 11, 6, 7, 14, 15);
    }

private:
    using Quad = float __attribute__((vector_size(16)));
    static FloatLanes join(const BoundingSphere& low, const BoundingSphere& high) {
        Quad a, b;
        std::memcpy(&a, &low, sizeof a);
        std::memcpy(&b, &high, sizeof b);
        return __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7);
    }
};

// Which of eight bounding spheres may the segment p + s·u (|u| = 1, |s| ≤ half_length) come within: the squared
// distance from a centre c is |(c − p) × u|² across the line plus (|s_c| − half_length)² beyond an end, where
// s_c = (c − p)·u. `margin` must cover float rounding: 2⁻¹⁸·(2|p| + max |centre|), with magnitude_bound(p) for |p|,
// is far above it (the rounding of p, u, c − p, the cross and dot products is a few 2⁻²⁴ of |p| and |c − p|), so a
// sphere the segment meets is never rejected; it widens both the reach and the half-length.
struct SegmentNearSpheres {
    SegmentNearSpheres(const Vec3d& p, const Vec3d& u, double half_length, double centre_bound)
        : px(float(p.x)), py(float(p.y)), pz(float(p.z)), ux(float(u.x)), uy(float(u.y)), uz(float(u.z)),
          margin(float(0x1p-18 * (2 * magnitude_bound(p) + centre_bound))),
          half(float(half_length * (1 + 0x1p-18)) + margin) {}

    unsigned test(const SphereLanes& s) const {
        ISOTRACE_FUSED_BOUNDS  // its margin is far above a rounding: fused or not, it keeps what the exact test keeps
        const FloatLanes fx = s.x - px, fy = s.y - py, fz = s.z - pz;
        const FloatLanes ax = fy * uz - fz * uy, ay = fz * ux - fx * uz, az = fx * uy - fy * ux;
        const FloatLanes along = fx * ux + fy * uy + fz * uz;
        const FloatLanes excess = abs(along) - half;
        const FloatLanes beyond = max(excess, FloatLanes{});
        const FloatLanes reach = s.radius * (1 + 0x1p-18f) + margin;
        return lane_bits((ax * ax + ay * ay + az * az + beyond * beyond) <= reach * reach);
    }

    float px, py, pz, ux, uy, uz, margin, half;
};

// Which of eight bounding spheres may contain the point p, with the same kind of margin (the rounding of p and of
// c − p is a few 2⁻²⁴ of |p| + |c|).
struct PointNearSpheres {
    PointNearSpheres(const Vec3d& p, double centre_bound)
        : px(float(p.x)), py(float(p.y)), pz(float(p.z)),
          margin(float(0x1p-18 * (2 * magnitude_bound(p) + centre_bound))) {}

    unsigned test(const SphereLanes& s) const {
        const FloatLanes fx = s.x - px, fy = s.y - py, fz = s.z - pz;
        const FloatLanes reach = s.radius * (1 + 0x1p-18f) + margin;
        return lane_bits((fx * fx + fy * fy + fz * fz) <= reach * reach);
    }

    float px, py, pz, margin;
};

// Tests the listed elements first, …, first + kLanes − 1 (the last group repeats the list's last element in the
// lanes beyond it, which the result leaves out): their indices in `group`, the lanes that pass as bits. Inlined:
// the callers' loops are the hot path of every cell query, where a call spills their vector registers.
template <class Test>
[[gnu::always_inline]] inline unsigned test_group(std::span<const std::uint32_t> ids,
                                                  std::span<const BoundingSphere> spheres, std::size_t first,
                                                  const Test& test, std::uint32_t (&group)[kLanes]) {
    const std::size_t n = ids.size();
    const BoundingSphere* lanes[kLanes];
    for (std::size_t k = 0; k < kLanes; ++k) {
        group[k] = ids[std::min(first + k, n - 1)];
        lanes[k] = &spheres[group[k]];
    }
    const unsigned lanes_in_list = n - first >= kLanes ? (1u << kLanes) - 1 : (1u << (n - first)) - 1;
    return test.test(SphereLanes(lanes)) & lanes_in_list;
}

// Calls visit(id) for the listed elements (in list order) whose bounding sphere passes `test`, kLanes at a time.
template <class Test, class Visit>
[[gnu::always_inline]] inline void for_each_near(std::span<const std::uint32_t> ids,
                                                 std::span<const BoundingSphere> spheres, const Test& test,
                                                 Visit&& visit) {
    for (std::size_t first = 0; first < ids.size(); first += kLanes) {
        std::uint32_t group[kLanes];
        // Most groups have no lane set: walking the set bits skips them at once.
        for (unsigned near = test_group(ids, spheres, first, test, group); near != 0; near &= near - 1)
            visit(group[std::countr_zero(near)]);
    }
}

// For each set of passing lanes (a bit each), their numbers in ascending order, one per byte from the lowest.
inline constexpr auto kPassingLanesFirst = [] {
    std::array<std::uint64_t, 1u << kLanes> table{};
    for (unsigned lanes = 0; lanes < table.size(); ++lanes) {
        int placed = 0;
        for (unsigned k = 0; k < unsigned(kLanes); ++k)
            if ((lanes >> k) & 1u) table[lanes] |= std::uint64_t(k) << (8 * placed++);
    }
    return table;
}();

// Appends to `out` the listed elements (in list order) whose bounding sphere passes `test`, kLanes at a time, without
// a branch per element: each group writes all its indices and keeps those that passed. For a list most of whose
// groups have a lane set (a cell query's), where for_each_near's walk mispredicted its exits.
template <class Test, class Out>
[[gnu::always_inline]] inline void append_near(std::span<const std::uint32_t> ids,
                                               std::span<const BoundingSphere> spheres, const Test& test, Out& out) {
    std::size_t kept = out.size();
    std::uint32_t* slot = out.room_for(ids.size() + kLanes) - kept;
    for (std::size_t first = 0; first < ids.size(); first += kLanes) {
        std::uint32_t group[kLanes];
        const unsigned near = test_group(ids, spheres, first, test, group);
#if defined(__AVX2__)
        // The passing lanes' indices moved to the front in one permute, all eight stored, `kept` advanced past
        // those that passed (a seventh of the test's instructions, lane by lane).
        __m256i indices;
        std::memcpy(&indices, group, sizeof indices);
        const __m256i order = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(std::int64_t(kPassingLanesFirst[near])));
        const __m256i packed = _mm256_permutevar8x32_epi32(indices, order);
        std::memcpy(slot + kept, &packed, sizeof packed);
        kept += std::size_t(std::popcount(near));
#else
        for (std::size_t k = 0; k < kLanes; ++k) {
            slot[kept] = group[k];
            kept += (near >> k) & 1u;
        }
#endif
    }
    out.extend_to(kept);
}

}  // namespace isotrace
