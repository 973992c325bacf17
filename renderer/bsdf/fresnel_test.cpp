#include "renderer/bsdf/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace isotrace {
namespace {

constexpr double kPi = std::numbers::pi;

// The textbook angle form (Hecht, "Optics", eq. 4.42-4.43), independent of the cosine form the code uses:
// R_s = sin^2(ti - tt) / sin^2(ti + tt), R_p = tan^2(ti - tt) / tan^2(ti + tt).
struct Polarised {
    double s, p;
};
Polarised fresnel_by_angles(double theta_i, double eta) {
    const double theta_t = std::asin(std::sin(theta_i) / eta);
    const double s = std::sin(theta_i - theta_t) / std::sin(theta_i + theta_t);
    const double p = std::tan(theta_i - theta_t) / std::tan(theta_i + theta_t);
    return {s * s, p * p};
}

TEST(FresnelDielectric, NormalIncidenceIsSquaredIorRatio) {
    for (float eta : {1.33f, 1.5f, 2.4f}) {
        const float expected = (eta - 1) * (eta - 1) / ((eta + 1) * (eta + 1));
        EXPECT_NEAR(fresnel_dielectric(1.0f, eta), expected, 1e-6f) << eta;
    }
}

TEST(FresnelDielectric, MatchesAngleFormAtSeveralAngles) {
    for (double degrees : {10.0, 30.0, 45.0, 60.0, 75.0, 89.0}) {
        const double theta = degrees * kPi / 180;
        const Polarised r = fresnel_by_angles(theta, 1.5);
        EXPECT_NEAR(fresnel_dielectric(float(std::cos(theta)), 1.5f), 0.5 * (r.s + r.p), 2e-6) << degrees;
    }
}

TEST(FresnelDielectric, BrewsterAngleLeavesOnlyTheSPolarisation) {
    const double brewster = std::atan(1.5);
    const Polarised r = fresnel_by_angles(brewster, 1.5);
    EXPECT_LT(r.p, 1e-12);
    EXPECT_NEAR(fresnel_dielectric(float(std::cos(brewster)), 1.5f), 0.5 * r.s, 1e-6);
}

TEST(FresnelDielectric, FromInsideInvertsTheIor) {
    for (float cos_theta : {1.0f, 0.9f, 0.8f, 0.75f}) {
        EXPECT_FLOAT_EQ(fresnel_dielectric(-cos_theta, 1.5f), fresnel_dielectric(cos_theta, 1 / 1.5f));
    }
}

TEST(FresnelDielectric, TotalInternalReflectionBeyondTheCriticalAngle) {
    const double critical = std::asin(1 / 1.5);
    EXPECT_LT(fresnel_dielectric(-float(std::cos(critical - 0.01)), 1.5f), 1.0f);
    for (double theta : {critical + 0.01, 1.2, kPi / 2}) {
        EXPECT_EQ(fresnel_dielectric(-float(std::cos(theta)), 1.5f), 1.0f) << theta;
    }
}

TEST(FresnelDielectric, GrazingIncidenceReflectsEverything) {
    EXPECT_NEAR(fresnel_dielectric(0.0f, 1.5f), 1.0f, 1e-6f);
}

TEST(FresnelConductor, WithoutAbsorptionEqualsDielectric) {
    const ComplexIor glass{Rgb(1.5f), Rgb(0.0f)};
    for (float cos_theta : {1.0f, 0.8f, 0.5f, 0.2f, 0.01f}) {
        const Rgb f = fresnel_conductor(cos_theta, glass);
        EXPECT_NEAR(f.g, fresnel_dielectric(cos_theta, 1.5f), 1e-6f) << cos_theta;
    }
}

TEST(FresnelConductor, NormalIncidenceClosedForm) {
    const ComplexIor metal{Rgb(0.2f, 1.0f, 2.5f), Rgb(3.5f, 2.5f, 0.5f)};
    const Rgb f = fresnel_conductor(1.0f, metal);
    const auto closed_form = [](float n, float k) { return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k); };
    EXPECT_NEAR(f.r, closed_form(0.2f, 3.5f), 1e-6f);
    EXPECT_NEAR(f.g, closed_form(1.0f, 2.5f), 1e-6f);
    EXPECT_NEAR(f.b, closed_form(2.5f, 0.5f), 1e-6f);
}

TEST(FresnelConductor, ReflectsEverythingAtGrazingIncidence) {
    const ComplexIor metal{Rgb(0.2f), Rgb(3.5f)};
    EXPECT_NEAR(fresnel_conductor(0.0f, metal).r, 1.0f, 1e-6f);
}

TEST(DiffuseFresnelReflectance, MatchesAngleFormQuadrature) {
    // 2 * integral of R(theta) cos(theta) sin(theta) dtheta with the angle form, by a fine midpoint rule.
    constexpr int steps = 20000;
    double sum = 0;
    for (int i = 0; i < steps; ++i) {
        const double theta = (i + 0.5) * (kPi / 2) / steps;
        const Polarised r = fresnel_by_angles(theta, 1.5);
        sum += 0.5 * (r.s + r.p) * 2 * std::cos(theta) * std::sin(theta) * (kPi / 2) / steps;
    }
    EXPECT_NEAR(diffuse_fresnel_reflectance(1.5f), sum, 1e-5);
    EXPECT_NEAR(diffuse_fresnel_reflectance(1.0f), 0.0, 1e-7);
}

}  // namespace
}  // namespace isotrace
