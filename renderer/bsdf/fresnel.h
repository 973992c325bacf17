#pragma once
// Fresnel reflectance of smooth interfaces, exact for unpolarised light (the mean of the s and p reflectances).
#include "renderer/math/rgb.h"

namespace isotrace {

// Complex index of refraction eta + i k per RGB channel (conductors; k = 0 is a dielectric).
struct ComplexIor {
    Rgb eta;
    Rgb k;
};

// Reflectance of a dielectric interface for light arriving at cos_theta_i from the side the normal points to,
// eta = IOR behind the interface / IOR in front. A negative cos_theta_i means arrival from behind, so eta is
// inverted. Returns 1 under total internal reflection.
float fresnel_dielectric(float cos_theta_i, float eta);

// Reflectance of a conductor (from a medium of IOR 1) at cos_theta_i in [0, 1], with the full complex-valued
// Fresnel equations rather than Schlick's approximation, so that k = 0 reproduces fresnel_dielectric.
Rgb fresnel_conductor(float cos_theta_i, const ComplexIor& ior);

// Schlick's approximation F0 + (1 - F0) (1 - cos_theta_i)^5, cos_theta_i in [0, 1] (clamped), of a surface given
// by its reflectance at normal incidence F0: per channel for an "artist" metal, F0 = ((eta - 1) / (eta + 1))^2 for
// a dielectric.
float fresnel_schlick(float cos_theta_i, float f0);
Rgb fresnel_schlick(float cos_theta_i, const Rgb& f0);
// Its cosine-weighted hemispherical average 2 * integral of F(mu) mu dmu = F0 + (1 - F0) / 21.
Rgb average_fresnel_schlick(const Rgb& f0);

// The cosine-weighted hemispherical average 2 * integral of F(mu) mu dmu of fresnel_dielectric for light
// arriving from the front (F_dr, "diffuse Fresnel reflectance"), by numerical quadrature.
float diffuse_fresnel_reflectance(float eta);

}  // namespace isotrace
