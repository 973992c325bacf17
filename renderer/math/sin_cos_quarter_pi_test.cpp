#include "renderer/math/sin_cos_quarter_pi.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace isotrace {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

// Within 1.25 ulp of the exact values on |x| <= pi/4 (every 4099th float of the range here; all of them when
// the polynomials were chosen).
TEST(SinCosQuarterPi, WithinAboutAnUlp) {
    const float limit = std::numbers::pi_v<float> / 4;
    int checked = 0;
    for (std::uint32_t u = 0; u <= bits(limit); u += 4099) {
        for (const float x : {std::bit_cast<float>(u), -std::bit_cast<float>(u)}) {
            float s, c;
            sin_cos_quarter_pi(x, s, c);
            const double exact_s = std::sin(double(x)), exact_c = std::cos(double(x));
            const double ulp_s = std::max(double(std::nextafter(std::abs(float(exact_s)), kInf) - std::abs(float(exact_s))),
                                          double(std::numeric_limits<float>::denorm_min()));
            const double ulp_c = std::nextafter(float(exact_c), kInf) - float(exact_c);
            ASSERT_LE(std::abs(s - exact_s), 1.25 * ulp_s) << x;
            ASSERT_LE(std::abs(c - exact_c), 1.25 * ulp_c) << x;
            ++checked;
        }
    }
    EXPECT_GT(checked, 200000);
}

}  // namespace
}  // namespace isotrace
