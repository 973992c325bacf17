#pragma once
// SurfaceBsdf: the scattering model a material builds at one shading point, held by value. The path tracer asks
// it for several values per bounce; one switch on the model's type per call (a variant) lets each model's code
// be inlined there, rather than a model allocated per hit and called through virtual functions, whose calls
// could not be inlined (docs/decisions.md). Empty for surfaces that scatter nothing (pure emitters).
#include <type_traits>
#include <utility>
#include <variant>

#include "renderer/bsdf/coated_diffuse_bsdf.h"
#include "renderer/bsdf/conductor_bsdf.h"
#include "renderer/bsdf/dielectric_bsdf.h"
#include "renderer/bsdf/lambert_bsdf.h"
#include "renderer/bsdf/principled_bsdf.h"

namespace isotrace {

class SurfaceBsdf {
    using Models = std::variant<std::monostate, LambertBsdf, ConductorBsdf, DielectricBsdf, CoatedDiffuseBsdf,
                                PrincipledBsdf>;

public:
    SurfaceBsdf() = default;  // scatters nothing
    // Implicit: any of the models is a SurfaceBsdf.
    template <class Model>
        requires(!std::is_same_v<Model, SurfaceBsdf> && std::is_constructible_v<Models, Model>)
    SurfaceBsdf(Model model) : model_(std::move(model)) {}  // NOLINT(google-explicit-constructor)

    bool scatters() const { return !std::holds_alternative<std::monostate>(model_); }

    // The members of every model (renderer/bsdf/bsdf.h); for an empty SurfaceBsdf: black, zero, no sample.
    Rgb eval(const Vec3f& wo, const Vec3f& wi, TransportMode mode = TransportMode::Radiance) const {
        return dispatch([&](const auto& m) { return m.eval(wo, wi, mode); }, Rgb());
    }
    float pdf(const Vec3f& wo, const Vec3f& wi) const {
        return dispatch([&](const auto& m) { return m.pdf(wo, wi); }, 0.0f);
    }
    std::optional<BsdfSample> sample(const Vec3f& wo, float u_lobe, std::array<float, 2> u,
                                     TransportMode mode = TransportMode::Radiance) const {
        return dispatch([&](const auto& m) { return m.sample(wo, u_lobe, u, mode); }, std::optional<BsdfSample>());
    }
    bool has_delta_lobe() const {
        return dispatch([](const auto& m) { return m.has_delta_lobe(); }, false);
    }
    bool is_fully_delta() const {
        return dispatch([](const auto& m) { return m.is_fully_delta(); }, false);
    }
    bool chooses_lobe() const {
        return dispatch([](const auto& m) { return m.chooses_lobe(); }, false);
    }

private:
    // A comparison per model, not std::visit: libstdc++'s visit calls each model through a table of function
    // pointers, which kept every model's code out of the path tracer's bounce. Forced inline, so that the caller
    // holds the models' calls directly and the small models inline there (docs/decisions.md).
    template <class Call, class Result>
    [[gnu::always_inline]] Result dispatch(Call&& call, Result none) const {
        return dispatch_from(call, none, std::make_index_sequence<std::variant_size_v<Models> - 1>());
    }
    static_assert(std::is_same_v<std::variant_alternative_t<0, Models>, std::monostate>, "index 0 scatters nothing");
    template <class Call, class Result, std::size_t... I>
    [[gnu::always_inline]] Result dispatch_from(Call& call, Result none, std::index_sequence<I...>) const {
        Result result = none;  // the empty model's (index 0)
        (void)((model_.index() == I + 1 && (result = call(*std::get_if<I + 1>(&model_)), true)) || ...);
        return result;
    }

    Models model_;
};

}  // namespace isotrace
