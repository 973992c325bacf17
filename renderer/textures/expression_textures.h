#pragma once
// Textures that are constants or expressions of other textures: mix, scale, offset, invert and the clamp that
// keeps a varying parameter inside its range. Each is constant when its inputs are (constant()), so that the
// parser can fold it into one ConstantTexture.
#include <memory>
#include <optional>

#include "renderer/plugin/texture.h"

namespace isotrace {

template <class T>
using TexturePtr = std::shared_ptr<const Texture<T>>;

template <class T>
class ConstantTexture final : public Texture<T> {
public:
    explicit ConstantTexture(const T& value) : value_(value) {}
    T evaluate(const TextureContext&) const override { return value_; }
    std::optional<T> constant() const override { return value_; }

private:
    T value_;
};

namespace texture_math {

inline float mix(float a, float b, float t) { return a * (1 - t) + b * t; }
inline Rgb mix(const Rgb& a, const Rgb& b, float t) { return a * (1 - t) + b * t; }
inline float invert(float v) { return 1 - v; }
inline Rgb invert(const Rgb& v) { return {1 - v.r, 1 - v.g, 1 - v.b}; }

}  // namespace texture_math

// a (1 - t) + b t.
template <class T>
class MixTexture final : public Texture<T> {
public:
    MixTexture(TexturePtr<T> a, TexturePtr<T> b, ScalarTexturePtr t) : a_(std::move(a)), b_(std::move(b)), t_(std::move(t)) {}
    T evaluate(const TextureContext& context) const override {
        return texture_math::mix(a_->evaluate(context), b_->evaluate(context), t_->evaluate(context));
    }
    std::optional<T> constant() const override {
        const auto a = a_->constant(), b = b_->constant();
        const auto t = t_->constant();
        if (!a || !b || !t) return std::nullopt;
        return texture_math::mix(*a, *b, *t);
    }
    TextureNeeds needs() const override {
        TextureNeeds needs = a_->needs();
        needs |= b_->needs();
        needs |= t_->needs();
        return needs;
    }

private:
    TexturePtr<T> a_, b_;
    ScalarTexturePtr t_;
};

// value × by, or value + by: a binary operation on two textures of one kind.
template <class T, class Operation>
class BinaryTexture final : public Texture<T> {
public:
    BinaryTexture(TexturePtr<T> value, TexturePtr<T> by) : value_(std::move(value)), by_(std::move(by)) {}
    T evaluate(const TextureContext& context) const override {
        return Operation{}(value_->evaluate(context), by_->evaluate(context));
    }
    std::optional<T> constant() const override {
        const auto value = value_->constant(), by = by_->constant();
        if (!value || !by) return std::nullopt;
        return Operation{}(*value, *by);
    }
    TextureNeeds needs() const override {
        TextureNeeds needs = value_->needs();
        needs |= by_->needs();
        return needs;
    }

private:
    TexturePtr<T> value_, by_;
};

struct Multiply {
    template <class T>
    T operator()(const T& a, const T& b) const { return a * b; }
};
struct Add {
    template <class T>
    T operator()(const T& a, const T& b) const { return a + b; }
};

template <class T>
using ScaleTexture = BinaryTexture<T, Multiply>;
template <class T>
using OffsetTexture = BinaryTexture<T, Add>;

// A texture transformed value by value: 1 - v (invert), or clamped into a range.
template <class T, class Function>
class UnaryTexture final : public Texture<T> {
public:
    UnaryTexture(TexturePtr<T> value, Function function) : value_(std::move(value)), function_(function) {}
    T evaluate(const TextureContext& context) const override { return function_(value_->evaluate(context)); }
    std::optional<T> constant() const override {
        const auto value = value_->constant();
        if (!value) return std::nullopt;
        return function_(*value);
    }
    TextureNeeds needs() const override { return value_->needs(); }

private:
    TexturePtr<T> value_;
    Function function_;
};

struct Invert {
    template <class T>
    T operator()(const T& v) const { return texture_math::invert(v); }
};

// Into [low, high] (each component of a colour); NaN becomes low.
struct Clamp {
    float low, high;
    float operator()(float v) const { return v >= low ? (v <= high ? v : high) : low; }
    Rgb operator()(const Rgb& v) const { return {(*this)(v.r), (*this)(v.g), (*this)(v.b)}; }
};

template <class T>
using InvertTexture = UnaryTexture<T, Invert>;
template <class T>
using ClampTexture = UnaryTexture<T, Clamp>;

}  // namespace isotrace
