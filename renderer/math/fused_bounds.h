#pragma once
// ISOTRACE_FUSED_BOUNDS, at the start of a block, lets clang fuse the block's multiplies and adds into FMA
// instructions where the target has them (the AVX2 modules, built with -mfma -ffp-contract=off: nothing else fuses).
// Only for arithmetic whose result is a bound tested with a margin far above one rounding (the sphere tests, the
// field's upper bounds before a sweep and on each piece): a fused and an unfused bound then prove the same things,
// so both builds report the same crossings, bit for bit, while the bounds' chains of dependent operations shorten
// (x1.03 on blobs_1k, docs/decisions.md). Values that reach a result (chords, sums, polynomials, roots) never fuse.
// GCC has no per-block contraction: there, and on baseline x86-64, the block is compiled as written.
#if defined(__clang__)
#define ISOTRACE_FUSED_BOUNDS _Pragma("clang fp contract(fast)")
#else
#define ISOTRACE_FUSED_BOUNDS
#endif

namespace isotrace {

// a·b + c as written (two roundings), and the same fused where the build has FMA: the one formula written once for
// values and for bounds (the multiply–add chosen by the caller).
struct RoundedMulAdd {
    template <class A, class B, class C>
    auto operator()(A a, B b, C c) const {
        return a * b + c;
    }
};
struct BoundMulAdd {
    template <class A, class B, class C>
    auto operator()(A a, B b, C c) const {
        ISOTRACE_FUSED_BOUNDS
        return a * b + c;
    }
};

}  // namespace isotrace
