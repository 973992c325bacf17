#pragma once
// Texture<T>: a material parameter that may vary over a surface — a constant, an image, a procedural pattern or an
// expression of them — evaluated at a shading point described by a TextureContext. T is float for scalar
// parameters (linear data: roughness, metallic, bump heights) and Rgb for colour parameters (in the working space;
// colour textures are converted from their own colour space when they are loaded). docs/textures.md lists the forms.
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "renderer/core/input_error.h"
#include "renderer/math/rgb.h"
#include "renderer/math/vec3.h"

namespace isotrace {

struct SurfaceHit;
class Shape;

// What a texture may read at a shading point, computed once per material evaluation.
struct TextureContext {
    Vec3f position;         // world space
    Vec3f normal;           // unit shading normal, world space
    Vec3f object_position;  // the object's own space (before its placement transform)
    Vec3f object_normal;    // unit, object space
    std::array<float, 2> uv{0, 0};
    Vec3f dpdu, dpdv;          // world space; zero where the shape has no uv
    float footprint = 0;       // world-space width of the pixel's footprint (0: point sampling, no filtering)
    float object_footprint = 0;  // the same in object-space units
    // Implicit shapes: the shape (Shape::field_value) and the point and unit normal in the shape's own space.
    const Shape* shape = nullptr;
    Vec3d shape_position;
    Vec3d shape_normal;

    TextureContext() = default;
    explicit TextureContext(const SurfaceHit& hit);
};

// What a texture needs from the surfaces it is put on, checked when the scene binds materials to objects so
// that a uv mapping on a surface without uv, or a field input on a surface without a field, is refused where it
// is written.
struct TextureNeeds {
    bool uv = false;
    bool field = false;
    SourceLocation where;  // of the first node that needs it
    std::string field_path;  // its JSON path
    TextureNeeds& operator|=(const TextureNeeds& other);
};

template <class T>
class Texture {
public:
    virtual ~Texture() = default;
    virtual T evaluate(const TextureContext& context) const = 0;
    // The value when it is the same everywhere (a constant, or an expression of constants), so that materials can
    // skip per-hit work.
    virtual std::optional<T> constant() const { return std::nullopt; }
    virtual TextureNeeds needs() const { return {}; }
};

using ScalarTexture = Texture<float>;
using ColourTexture = Texture<Rgb>;
using ScalarTexturePtr = std::shared_ptr<const ScalarTexture>;
using ColourTexturePtr = std::shared_ptr<const ColourTexture>;

}  // namespace isotrace
