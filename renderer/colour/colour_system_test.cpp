#include "renderer/colour/colour_system.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <thread>

#include "tests/support/scoped_environment_variable.h"

namespace OCIO = OCIO_NAMESPACE;

namespace isotrace {
namespace {

const std::string kAcescg = "ACEScg";
const std::string kLinearRec709 = "Linear Rec.709 (sRGB)";
const std::string kSdrVideoView = "ACES 1.0 - SDR Video";
const std::string kUntonemappedView = "Un-tone-mapped";

// The config shipped with isotrace, whatever $OCIO says in the environment running the tests.
std::string shipped_config() {
    ScopedEnvironmentVariable unset("OCIO", std::nullopt);
    return default_ocio_config_path();
}

// The sRGB encoding (IEC 61966-2-1), written out independently of OCIO.
double srgb_encode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

void expect_rgb_near(const Rgb& actual, const Rgb& expected, float tolerance) {
    EXPECT_NEAR(actual.r, expected.r, tolerance);
    EXPECT_NEAR(actual.g, expected.g, tolerance);
    EXPECT_NEAR(actual.b, expected.b, tolerance);
}

// --- Reference matrix derived from published primaries ------------------------------------------

using Matrix = std::array<std::array<double, 3>, 3>;

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix product{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) product[i][j] += a[i][k] * b[k][j];
    return product;
}

Matrix inverse(const Matrix& m) {
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Matrix result{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            // Cofactor of (j, i), by cyclic index trick, gives the adjugate directly.
            const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            result[i][j] = (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) / det;
        }
    return result;
}

std::array<double, 3> xy_to_xyz(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

// RGB -> CIE XYZ for primaries and white given as CIE 1931 xy (SMPTE RP 177 method).
Matrix rgb_to_xyz(const std::array<std::array<double, 2>, 3>& primaries, std::array<double, 2> white) {
    Matrix columns{};
    for (int c = 0; c < 3; ++c) {
        const auto xyz = xy_to_xyz(primaries[c][0], primaries[c][1]);
        for (int i = 0; i < 3; ++i) columns[i][c] = xyz[i];
    }
    const Matrix to_primaries = inverse(columns);
    const auto w = xy_to_xyz(white[0], white[1]);
    for (int c = 0; c < 3; ++c) {
        const double scale =
            to_primaries[c][0] * w[0] + to_primaries[c][1] * w[1] + to_primaries[c][2] * w[2];
        for (int i = 0; i < 3; ++i) columns[i][c] *= scale;
    }
    return columns;
}

// Bradford chromatic adaptation (Lam 1985, as used by ICC and ACES) from one white to another.
Matrix bradford(std::array<double, 2> from_white, std::array<double, 2> to_white) {
    const Matrix cone = {{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
    const auto cone_response = [&](std::array<double, 2> white) {
        const auto xyz = xy_to_xyz(white[0], white[1]);
        std::array<double, 3> lms{};
        for (int i = 0; i < 3; ++i) lms[i] = cone[i][0] * xyz[0] + cone[i][1] * xyz[1] + cone[i][2] * xyz[2];
        return lms;
    };
    const auto from = cone_response(from_white), to = cone_response(to_white);
    Matrix scale{};
    for (int i = 0; i < 3; ++i) scale[i][i] = to[i] / from[i];
    return multiply(inverse(cone), multiply(scale, cone));
}

// ACEScg (AP1) -> linear Rec.709. AP1 primaries and the ACES white from ACES spec S-2014-004
// (ACEScg); Rec.709 primaries and D65 from ITU-R BT.709-6 table 1.
Matrix acescg_to_rec709_reference() {
    const std::array<double, 2> aces_white = {0.32168, 0.33767}, d65 = {0.3127, 0.3290};
    const Matrix ap1_to_xyz = rgb_to_xyz({{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}}}, aces_white);
    const Matrix rec709_to_xyz = rgb_to_xyz({{{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}}, d65);
    return multiply(inverse(rec709_to_xyz), multiply(bradford(aces_white, d65), ap1_to_xyz));
}

// --- Tests ---------------------------------------------------------------------------------------

TEST(ColourSystem, LoadsTheShippedConfig) {
    const ColourSystem colour(shipped_config());
    EXPECT_EQ(colour.working_space(), kAcescg);
    EXPECT_EQ(colour.default_display(), "sRGB");
    EXPECT_EQ(colour.displays(), std::vector<std::string>{"sRGB"});
    EXPECT_EQ(colour.default_view(), kSdrVideoView);
    EXPECT_EQ(colour.views(), (std::vector<std::string>{kSdrVideoView, kUntonemappedView}));
    for (const char* name : {"ACES2065-1", "ACEScg", "Linear Rec.709 (sRGB)", "sRGB - Texture", "Raw"})
        EXPECT_TRUE(colour.has_colour_space(name)) << name;
}

TEST(ColourSystem, EveryViewOfTheDefaultDisplayConverts) {
    const ColourSystem colour(shipped_config());
    for (const std::string& view : colour.views()) {
        std::array<float, 3> grey = {0.18f, 0.18f, 0.18f};
        colour.to_display(grey.data(), 1, 3, colour.default_display(), view);
        EXPECT_GT(grey[0], 0.1f) << view;
        EXPECT_LT(grey[0], 0.9f) << view;
    }
}

TEST(ColourSystem, AliasesResolveToCanonicalNames) {
    const std::string config = shipped_config();
    const std::vector<std::pair<std::string, std::string>> aliases = {{"acescg", "ACEScg"},
                                                                      {"lin_rec709", kLinearRec709},
                                                                      {"srgb_linear", kLinearRec709},
                                                                      {"srgb_texture", "sRGB - Texture"},
                                                                      {"srgb", "sRGB - Texture"},
                                                                      {"aces2065_1", "ACES2065-1"},
                                                                      {"raw", "Raw"}};
    for (const auto& [alias, canonical] : aliases) {
        if (alias != "srgb_texture" && alias != "srgb" && alias != "raw") {  // not scene-linear: no working space
            EXPECT_EQ(ColourSystem(config, alias).working_space(), canonical) << alias;
        }
        const ColourSystem colour(config);
        expect_rgb_near(colour.to_working(Rgb(0.2f, 0.5f, 0.8f), alias),
                        colour.to_working(Rgb(0.2f, 0.5f, 0.8f), canonical), 0.0f);
    }
}

TEST(ColourSystem, AcescgToLinearRec709MatchesMatrixDerivedFromPrimaries) {
    const ColourSystem colour(shipped_config(), kLinearRec709);
    const Matrix reference = acescg_to_rec709_reference();
    // Sanity check of the derivation against the commonly published rounded matrix.
    EXPECT_NEAR(reference[0][0], 1.70505, 1e-4);
    EXPECT_NEAR(reference[1][1], 1.14080, 1e-4);
    EXPECT_NEAR(reference[2][2], 1.15297, 1e-4);

    const std::array<Rgb, 3> unit_primaries = {Rgb(1, 0, 0), Rgb(0, 1, 0), Rgb(0, 0, 1)};
    for (int column = 0; column < 3; ++column) {
        const Rgb converted = colour.to_working(unit_primaries[column], kAcescg);
        const Rgb expected(static_cast<float>(reference[0][column]), static_cast<float>(reference[1][column]),
                           static_cast<float>(reference[2][column]));
        expect_rgb_near(converted, expected, 1e-4f);
    }
}

TEST(ColourSystem, AcescgLinearRec709RoundTripIsIdentity) {
    const std::string config = shipped_config();
    const ColourSystem into_rec709(config, kLinearRec709);
    const ColourSystem into_acescg(config, kAcescg);
    for (const Rgb& value : {Rgb(1, 0, 0), Rgb(0, 1, 0), Rgb(0, 0, 1), Rgb(0.18f), Rgb(0.9f, 0.4f, 0.05f)}) {
        const Rgb round_trip = into_acescg.to_working(into_rec709.to_working(value, kAcescg), kLinearRec709);
        expect_rgb_near(round_trip, value, 1e-6f);
    }
}

TEST(ColourSystem, WhiteStaysWhiteBetweenAcescgAndRec709) {
    const ColourSystem colour(shipped_config(), kLinearRec709);
    expect_rgb_near(colour.to_working(Rgb(1.0f), kAcescg), Rgb(1.0f), 1e-4f);
}

TEST(ColourSystem, SrgbTextureDecodesWithTheSrgbEotf) {
    const ColourSystem colour(shipped_config(), kLinearRec709);
    // ((0.5 + 0.055) / 1.055)^2.4 = 0.214041 (IEC 61966-2-1).
    expect_rgb_near(colour.to_working(Rgb(0.5f), "sRGB - Texture"), Rgb(0.214041f), 1e-5f);
}

TEST(ColourSystem, BufferConversionMatchesSingleValuesAndKeepsAlpha) {
    const ColourSystem colour(shipped_config());
    std::vector<float> rgba = {0.5f, 0.25f, 1.0f, 0.3f, 0.0f, 0.75f, 0.1f, 0.9f};
    colour.to_working(rgba.data(), 2, 4, "srgb_texture");
    for (int pixel = 0; pixel < 2; ++pixel) {
        const float* p = &rgba[pixel * 4];
        const Rgb expected =
            colour.to_working(pixel == 0 ? Rgb(0.5f, 0.25f, 1.0f) : Rgb(0.0f, 0.75f, 0.1f), "srgb_texture");
        expect_rgb_near(Rgb(p[0], p[1], p[2]), expected, 1e-6f);
    }
    EXPECT_EQ(rgba[3], 0.3f);
    EXPECT_EQ(rgba[7], 0.9f);
}

TEST(ColourSystem, RawDataIsNeverConverted) {
    const ColourSystem colour(shipped_config());
    EXPECT_EQ(colour.to_working(Rgb(0.5f, -1.0f, 7.0f), "Raw"), Rgb(0.5f, -1.0f, 7.0f));
}

TEST(ColourSystem, UntonemappedViewIsThePlainSrgbEncoding) {
    const ColourSystem colour(shipped_config(), kLinearRec709);
    std::array<float, 3> grey = {0.18f, 0.18f, 0.18f};
    colour.to_display(grey.data(), 1, 3, "sRGB", kUntonemappedView);
    const float expected = static_cast<float>(srgb_encode(0.18));  // 0.46135
    EXPECT_NEAR(expected, 0.46135f, 1e-5f);
    for (float channel : grey) EXPECT_NEAR(channel, expected, 1e-4f);
}

// ACES 1.0 has no closed form, so compare with a processor built directly with OCIO from the same
// names, and check the properties every tone curve must have.
TEST(ColourSystem, AcesSdrVideoViewMatchesOcioAndIsAToneCurve) {
    const std::string config_path = shipped_config();
    const ColourSystem colour(config_path);

    OCIO::DisplayViewTransformRcPtr display_view = OCIO::DisplayViewTransform::Create();
    display_view->setSrc(kAcescg.c_str());
    display_view->setDisplay("sRGB");
    display_view->setView(kSdrVideoView.c_str());
    const OCIO::ConstCPUProcessorRcPtr independent = OCIO::Config::CreateFromFile(config_path.c_str())
                                                         ->getProcessor(display_view)
                                                         ->getDefaultCPUProcessor();

    std::array<float, 3> ours = {0.18f, 0.18f, 0.18f}, theirs = ours;
    colour.to_display(ours.data(), 1, 3);
    independent->applyRGB(theirs.data());
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ours[c], theirs[c], 1e-6f);
    // Neutral grey passes the RRT/ODT colour steps unchanged, so it follows the ACES 1.0 design
    // points (ODT.Academy.RGBmonitor_100nits_dim.ctl): scene 0.18 -> 4.8 cd/m2 on the 0.02..48 cd/m2
    // tone scale, normalised, then the dim-surround gamma 0.9811, then sRGB-encoded: 0.35597.
    // OCIO 2.1.2 gives 0.355954.
    const double tone_scaled = (4.8 - 0.02) / (48.0 - 0.02);
    const float expected_grey = static_cast<float>(srgb_encode(std::pow(tone_scaled, 0.9811)));
    EXPECT_NEAR(ours[0], expected_grey, 1e-3f);
    EXPECT_NEAR(ours[1], ours[0], 1e-3f);
    EXPECT_NEAR(ours[2], ours[0], 1e-3f);

    std::vector<float> ramp;
    for (float stop = -12.0f; stop <= 12.0f; stop += 0.25f) ramp.insert(ramp.end(), 3, std::exp2(stop));
    ramp.insert(ramp.end(), {0.0f, 0.0f, 0.0f, 1e6f, 1e6f, 1e6f});
    colour.to_display(ramp.data(), ramp.size() / 3, 3);
    const std::size_t zero = ramp.size() - 6, huge = ramp.size() - 3;
    for (std::size_t i = 3; i < zero; i += 3) EXPECT_GE(ramp[i], ramp[i - 3]) << "at sample " << i / 3;
    EXPECT_NEAR(ramp[zero], 0.0f, 1e-3f);
    EXPECT_LE(ramp[huge], 1.0f);
    EXPECT_GT(ramp[huge], 0.99f);
}

TEST(ColourSystem, ConcurrentConversionsAgree) {
    const ColourSystem colour(shipped_config());
    std::array<Rgb, 4> results;
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < results.size(); ++t)
        threads.emplace_back(
            [&, t] { results[t] = colour.to_working(Rgb(0.5f, 0.2f, 0.1f), "sRGB - Texture"); });
    for (std::thread& thread : threads) thread.join();
    for (const Rgb& result : results) EXPECT_EQ(result, results[0]);
}

TEST(ColourSystem, UnknownWorkingSpaceSuggestsTheClosestName) {
    try {
        ColourSystem(shipped_config(), "ACEScgg");
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.field(), "working_space");
        EXPECT_NE(std::string(error.what()).find("did you mean \"ACEScg\"?"), std::string::npos)
            << error.what();
    }
}

TEST(ColourSystem, WorkingSpaceThatIsNotSceneLinearIsRejected) {
    for (const std::string space : {"srgb_texture", "ACEScct", "Raw", "sRGB - Display"}) {
        try {
            ColourSystem(shipped_config(), space);
            FAIL() << "expected InputError for " << space;
        } catch (const InputError& error) {
            EXPECT_EQ(error.field(), "working_space");
            EXPECT_NE(std::string(error.what()).find("must be scene-linear"), std::string::npos) << error.what();
        }
    }
}

TEST(ColourSystem, UnloadableConfigFromTheOcioVariableSaysItCameFromThere) {
    const ScopedEnvironmentVariable ocio("OCIO", std::string("/nonexistent/from_env.ocio"));
    try {
        ColourSystem("", "ACEScg");
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.field(), "$OCIO");
        EXPECT_NE(std::string(error.what()).find("/nonexistent/from_env.ocio"), std::string::npos) << error.what();
    }
}

TEST(ColourSystem, RolesAreAcceptedAndSuggested) {
    const ColourSystem colour(shipped_config(), "scene_linear");
    EXPECT_EQ(colour.working_space(), kAcescg);
    try {
        colour.to_working(Rgb(1.0f), "texture paint");
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("did you mean \"texture_paint\"?"), std::string::npos)
            << error.what();
    }
}

TEST(ColourSystem, UnknownSourceSpaceIsReportedWhereTheSceneNamesIt) {
    const ColourSystem colour(shipped_config());
    try {
        colour.to_working(Rgb(1.0f), "srgb_textur", SourceLocation{"scene.json", 12, 7},
                          "materials[0].albedo");
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind("scene.json:12:7: materials[0].albedo: ", 0), 0u) << message;
        EXPECT_NE(message.find("did you mean \"srgb_texture\"?"), std::string::npos) << message;
    }
    EXPECT_THROW(colour.to_working(nullptr, 0, 3, "Rec.2020"), InputError);
}

TEST(ColourSystem, UnknownViewOrDisplayListsTheChoices) {
    const ColourSystem colour(shipped_config());
    std::array<float, 3> pixel = {0.18f, 0.18f, 0.18f};
    try {
        colour.to_display(pixel.data(), 1, 3, "sRGB", "Untonemapped");
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("did you mean \"Un-tone-mapped\"?"), std::string::npos)
            << error.what();
    }
    try {
        colour.to_display(pixel.data(), 1, 3, "Rec.2100-PQ");
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("valid choices: \"sRGB\""), std::string::npos)
            << error.what();
    }
    EXPECT_THROW(colour.views("P3"), InputError);
}

TEST(ColourSystem, UnloadableConfigNamesTheFile) {
    try {
        ColourSystem("/nonexistent/broken.ocio");
        FAIL() << "expected InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.location().file, "/nonexistent/broken.ocio");
        EXPECT_NE(std::string(error.what()).find("/nonexistent/broken.ocio"), std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace isotrace
