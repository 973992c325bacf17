#include "renderer/textures/expression_textures.h"

#include <gtest/gtest.h>

namespace isotrace {
namespace {

// A varying scalar: the context's u.
class UTexture final : public ScalarTexture {
public:
    float evaluate(const TextureContext& context) const override { return context.uv[0]; }
};

TextureContext at_u(float u) {
    TextureContext context;
    context.uv = {u, 0};
    return context;
}

template <class T>
TexturePtr<T> constant(const T& value) {
    return std::make_shared<ConstantTexture<T>>(value);
}

TEST(ExpressionTextures, ConstantsAreConstant) {
    const auto grey = constant(Rgb(0.25f, 0.5f, 0.75f));
    EXPECT_EQ(grey->evaluate(at_u(0.3f)), Rgb(0.25f, 0.5f, 0.75f));
    EXPECT_EQ(grey->constant(), Rgb(0.25f, 0.5f, 0.75f));
    EXPECT_FALSE(UTexture().constant());
}

TEST(ExpressionTextures, MixAtKnownValues) {
    const auto u = std::make_shared<UTexture>();
    const MixTexture<Rgb> mix(constant(Rgb(0, 1, 2)), constant(Rgb(4, 5, 10)), u);
    EXPECT_EQ(mix.evaluate(at_u(0)), Rgb(0, 1, 2));
    EXPECT_EQ(mix.evaluate(at_u(1)), Rgb(4, 5, 10));
    EXPECT_EQ(mix.evaluate(at_u(0.25f)), Rgb(1, 2, 4));
    EXPECT_FALSE(mix.constant());
    const MixTexture<float> constant_mix(constant(2.0f), constant(6.0f), constant(0.75f));
    EXPECT_EQ(constant_mix.constant(), 5.0f);
}

TEST(ExpressionTextures, ScaleOffsetInvertAtKnownValues) {
    const auto u = std::make_shared<UTexture>();
    EXPECT_EQ(ScaleTexture<float>(u, constant(3.0f)).evaluate(at_u(0.5f)), 1.5f);
    EXPECT_EQ(OffsetTexture<float>(u, constant(-0.25f)).evaluate(at_u(0.5f)), 0.25f);
    EXPECT_EQ(InvertTexture<float>(u, Invert{}).evaluate(at_u(0.25f)), 0.75f);
    EXPECT_EQ(ScaleTexture<Rgb>(constant(Rgb(1, 2, 3)), constant(Rgb(2, 0.5f, 1))).constant(), Rgb(2, 1, 3));
    EXPECT_EQ(OffsetTexture<Rgb>(constant(Rgb(1, 2, 3)), constant(Rgb(0.5f))).constant(), Rgb(1.5f, 2.5f, 3.5f));
    EXPECT_EQ(InvertTexture<Rgb>(constant(Rgb(0, 0.25f, 2)), Invert{}).constant(), Rgb(1, 0.75f, -1));
    EXPECT_FALSE((ScaleTexture<float>(u, constant(3.0f)).constant()));
}

TEST(ExpressionTextures, ClampKeepsValuesInRange) {
    const auto u = std::make_shared<UTexture>();
    const ClampTexture<float> clamped(u, Clamp{0, 1});
    EXPECT_EQ(clamped.evaluate(at_u(-3)), 0.0f);
    EXPECT_EQ(clamped.evaluate(at_u(0.5f)), 0.5f);
    EXPECT_EQ(clamped.evaluate(at_u(7)), 1.0f);
    EXPECT_EQ(Clamp({0, 1})(Rgb(-1, 0.5f, 2)), Rgb(0, 0.5f, 1));
    EXPECT_EQ(Clamp({0.25f, 1})(NAN), 0.25f);  // a NaN from an overflowing expression must not reach a BSDF
}

TEST(ExpressionTextures, NeedsKeepTheFirstNodeThatNeeds) {
    struct Needing final : public ScalarTexture {
        TextureNeeds what;
        explicit Needing(TextureNeeds n) : what(std::move(n)) {}
        float evaluate(const TextureContext&) const override { return 0; }
        TextureNeeds needs() const override { return what; }
    };
    const auto uv = std::make_shared<Needing>(TextureNeeds{.uv = true, .where = {"s.json", 3, 4}, .field_path = "a"});
    const auto field = std::make_shared<Needing>(TextureNeeds{.field = true, .where = {"s.json", 5, 6}, .field_path = "b"});
    const TextureNeeds needs = MixTexture<float>(constant(0.0f), uv, field).needs();
    EXPECT_TRUE(needs.uv);
    EXPECT_TRUE(needs.field);
    EXPECT_EQ(needs.where.line, 3);
    EXPECT_EQ(needs.field_path, "a");
    EXPECT_FALSE(MixTexture<float>(constant(0.0f), constant(1.0f), constant(0.5f)).needs().uv);
}

}  // namespace
}  // namespace isotrace
