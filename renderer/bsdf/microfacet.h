#pragma once
// Pieces of the microfacet scattering model (Walter et al. 2007, "Microfacet Models for Refraction through
// Rough Surfaces") shared by the GGX-based BSDFs.
#include <optional>

#include "renderer/bsdf/ggx.h"

namespace isotrace {

// The microfacet normal that scatters wo into wi: the generalised half vector wo + eta wi, eta = 1 for
// reflection and IOR on wi's side / IOR on wo's side for refraction, turned into the upper hemisphere. Empty
// when it is degenerate or when wo or wi would see that microfacet from behind.
std::optional<Vec3f> microfacet_normal(const Vec3f& wo, const Vec3f& wi, float eta);

// D(m) G2(wo, wi) / (4 |wo.z| |wi.z|): the reflection BRDF through microfacet m, without Fresnel.
float microfacet_reflection(const GgxDistribution& ggx, const Vec3f& wo, const Vec3f& wi, const Vec3f& m);

// Density of wi = reflect(wo, m) when m is drawn from the normals visible from wo: D_wo(m) / (4 |wo.m|).
float microfacet_reflection_pdf(const GgxDistribution& ggx, const Vec3f& wo, const Vec3f& m);

}  // namespace isotrace
