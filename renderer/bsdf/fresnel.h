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

// The cosine-weighted hemispherical average 2 * integral of F(mu) mu dmu of fresnel_dielectric for light
// arriving from the front (F_dr, "diffuse Fresnel reflectance"), by numerical quadrature.
float diffuse_fresnel_reflectance(float eta);

}  // namespace isotrace
