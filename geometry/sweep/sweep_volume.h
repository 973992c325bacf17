#pragma once
// Volume enclosed by a sweep between t = 0 and t = 1 (its end sections closing it).
//
// Paper, eq. (3): V = ∫ A(t)·⟨N(t), C′(t)⟩ dt, A = ½∮ r² dθ. The general form follows from the velocity of a
// section point C + R·p, p = (x, y, 0): its normal component is ⟨C′, N⟩ + (ω × p)_z = ⟨C′, N⟩ + ω_x·y − ω_y·x with
// RᵀR′ = [ω]ₓ, so V = ∫ (A·⟨N, C′⟩ + ω_x·M_y − ω_y·M_x) dt with the first moments M_x = ⅓∮ r³ cos θ dθ and
// M_y = ⅓∮ r³ sin θ dθ. Eq. (3) drops the moment term: exact only when each section's centroid lies on C(t) (or
// the sections do not turn); an offset disc swept round a circle is off by 2π·A·e (Pappus). Both assume the
// sections never sweep back through each other.
namespace isotrace {

class SweepSurface;

struct SectionIntegrals {
    double area = 0;      // ½∮ r² dθ
    double moment_x = 0;  // ∫∫ x dA in the section's frame
    double moment_y = 0;  // ∫∫ y dA
};

// Gauss–Legendre on every knot interval of r in θ (exact for the area of the piecewise-cubic r).
SectionIntegrals section_integrals(const SweepSurface& sweep, double t);

// Eq. (3) and the general form, by Gauss–Legendre over `intervals` equal pieces of t.
double paper_volume(const SweepSurface& sweep, int intervals = 256);
double sweep_volume(const SweepSurface& sweep, int intervals = 256);

}  // namespace isotrace
