#include "renderer/textures/texture_parser.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>

#include "renderer/colour/colour_system.h"
#include "renderer/core/did_you_mean.h"
#include "renderer/core/enum_names.h"
#include "renderer/params/emitted_colour.h"
#include "renderer/textures/expression_textures.h"
#include "renderer/textures/field_texture.h"
#include "renderer/textures/image_map_texture.h"
#include "renderer/textures/pattern_texture.h"

namespace isotrace {
namespace {

template <class T>
constexpr bool kIsColour = std::is_same_v<T, Rgb>;

// Whether an object node writes `key` (without marking it as known to SceneNode::finish).
bool writes(const SceneNode& node, const std::string& key) {
    return node.json().is_object() && node.json().find(key) != nullptr;
}

// An image's channel for a number.
constexpr EnumName<ImageContent> kChannelNames[] = {{ImageContent::Red, "r"},
                                                    {ImageContent::Green, "g"},
                                                    {ImageContent::Blue, "b"},
                                                    {ImageContent::Alpha, "a"},
                                                    {ImageContent::Luminance, "luminance"}};
// The values of "wrap", the default first.
constexpr EnumName<WrapMode> kWrapNames[] = {
    {WrapMode::Repeat, "repeat"}, {WrapMode::Clamp, "clamp"}, {WrapMode::Mirror, "mirror"}};

std::string listed(const std::vector<std::string>& names) {
    std::string list;
    for (const auto& name : names) list += (list.empty() ? "" : ", ") + name;
    return list;
}

std::string shortest(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

template <class T>
TexturePtr<T> constant_texture(const T& value) {
    return std::make_shared<ConstantTexture<T>>(value);
}

bool is_finite(float v) { return std::isfinite(v); }
bool is_finite(const Rgb& v) { return v.is_finite(); }

// A constant written at `node` (or an expression of constants there), which must be a finite float: JSON numbers
// are doubles, and one beyond float's range (or an expression that overflows) would put infinities and NaNs in
// the image.
template <class T>
TexturePtr<T> finite_constant(const SceneNode& node, const T& value) {
    if (!is_finite(value)) node.fail("the value overflows a float (its magnitude must stay below 3.4e38)");
    return constant_texture(value);
}

// An expression of constants becomes the constant it evaluates to.
template <class T>
TexturePtr<T> folded(const SceneNode& node, TexturePtr<T> texture) {
    if (const auto value = texture->constant()) return finite_constant(node, *value);
    return texture;
}

class TextureParser {
public:
    // `data_images`: colour images are data (no colour conversion).
    explicit TextureParser(bool data_images) : data_images_(data_images) {}

    // Any value of a parameter of kind T, `depth` levels deep.
    template <class T>
    TexturePtr<T> value(const SceneNode& node, int depth) const {
        if (depth > kMaxTextureDepth)
            node.fail("textures nest more than " + std::to_string(kMaxTextureDepth) + " levels deep here");
        const JsonValue& json = node.json();
        if (json.is_object() && json.find("type")) return typed<T>(node, depth);
        if constexpr (kIsColour<T>) {
            if (json.is_object() && json.find("texture")) return short_form(node);
            if (json.is_number() || json.is_array() || (json.is_object() && json.find("rgb")))
                return finite_constant(node, node.as_colour());
            node.fail("expected a colour ([r, g, b], a number, {\"rgb\": [r, g, b], \"space\": name}) or a texture "
                      "({\"type\": ...}, {\"texture\": file})");
        } else {
            if (json.is_number()) return finite_constant(node, float(node.as_number()));
            if (json.is_array() || (json.is_object() && (json.find("rgb") || json.find("texture"))))
                node.fail("expected a number or a scalar texture ({\"type\": ...}): this parameter is a number, not a "
                          "colour");
            node.fail("expected a number or a texture ({\"type\": ...})");
        }
    }

private:
    template <class T>
    static std::vector<std::string> types() {
        std::vector<std::string> names{"image", "mix", "scale", "offset", "invert"};
        names.insert(names.end(), pattern_types().begin(), pattern_types().end());
        if constexpr (!kIsColour<T>) names.push_back("field");
        return names;
    }

    // parent[key], which must be written, of kind T.
    template <class T>
    TexturePtr<T> required(const SceneNode& parent, const std::string& key, int depth) const {
        const auto child = parent.optional_value(key);
        if (!child) parent.fail("missing required field \"" + key + "\"");
        return value<T>(*child, depth);
    }

    // parent[key] of kind T, or `fallback` when it is not written.
    template <class T>
    TexturePtr<T> optional(const SceneNode& parent, const std::string& key, int depth, const T& fallback) const {
        const auto child = parent.optional_value(key);
        return child ? value<T>(*child, depth) : constant_texture(fallback);
    }

    // mix(a, b, pattern): a and b default to 0 and 1 (black and white).
    template <class T>
    TexturePtr<T> pattern(const SceneNode& node, const std::string& type, int depth) const {
        ScalarTexturePtr t = parse_pattern(node, type);
        const bool mixed = writes(node, "a") || writes(node, "b");
        TexturePtr<T> a = optional<T>(node, "a", depth + 1, T(0)), b = optional<T>(node, "b", depth + 1, T(1));
        if constexpr (!kIsColour<T>)
            if (!mixed) return t;
        return std::make_shared<MixTexture<T>>(std::move(a), std::move(b), std::move(t));
    }

    template <class T>
    TexturePtr<T> typed(const SceneNode& node, int depth) const {
        const std::string type = node.string("type");
        TexturePtr<T> result;
        const auto& patterns = pattern_types();
        if (type == "image") {
            result = image<T>(node);
        } else if (std::find(patterns.begin(), patterns.end(), type) != patterns.end()) {
            result = pattern<T>(node, type, depth);
        } else if (type == "mix") {
            result = std::make_shared<MixTexture<T>>(required<T>(node, "a", depth + 1), required<T>(node, "b", depth + 1),
                                                     required<float>(node, "t", depth + 1));
        } else if (type == "scale") {
            result = std::make_shared<ScaleTexture<T>>(required<T>(node, "value", depth + 1),
                                                       required<T>(node, "by", depth + 1));
        } else if (type == "offset") {
            result = std::make_shared<OffsetTexture<T>>(required<T>(node, "value", depth + 1),
                                                        required<T>(node, "by", depth + 1));
        } else if (type == "invert") {
            result = std::make_shared<InvertTexture<T>>(required<T>(node, "value", depth + 1), Invert{});
        } else if (type == "field" && kIsColour<T>) {
            node.fail_at("type", "\"field\" gives a number, not a colour: use it where a number is expected, such as "
                                 "a mix's \"t\"");
        } else if constexpr (!kIsColour<T>) {
            if (type == "field") result = field(node);
        }
        if (!result) {
            const std::vector<std::string> known = types<T>();
            node.fail_at("type", "unknown texture type \"" + type + "\"" + did_you_mean(type, known) +
                                     "; expected one of: " + listed(known));
        }
        node.finish();
        return folded<T>(node, std::move(result));
    }

    static ScalarTexturePtr field(const SceneNode& node) {
        const bool gradient = node.choice_or("output", "value", {"value", "gradient"}) == "gradient";
        const double depth = node.number_or("depth", 0.0);
        return std::make_shared<FieldTexture>(gradient ? FieldTexture::Output::Gradient : FieldTexture::Output::Value,
                                              depth, TextureNeeds{.field = true, .where = node.location(), .field_path = node.path()});
    }

    // The colour space of a colour image ("" for the default); data images have none.
    std::string image_colour_space(const SceneNode& node) const {
        if (!data_images_) return node.string_or("space", "");
        if (writes(node, "space"))
            node.fail_at("space", "this image is data, used as stored: it has no colour space");
        return "";
    }

    template <class T>
    TexturePtr<T> image(const SceneNode& node) const {
        ImageLoadOptions options{.content = data_images_ ? ImageContent::Data : ImageContent::Colour, .mip_levels = true};
        std::string space;
        if constexpr (kIsColour<T>) {
            if (writes(node, "channel"))
                node.fail_at("channel", "\"channel\" picks one channel for a number; a colour takes the image's RGB");
            space = image_colour_space(node);
        } else {
            if (writes(node, "space"))
                node.fail_at("space", "a number's image is data, used as stored: it has no colour space");
            if (!writes(node, "channel"))
                node.fail("an image for a number needs \"channel\": one of " + listed(enum_names(kChannelNames)));
            options.content = enum_value(kChannelNames, node.choice_or("channel", "", enum_names(kChannelNames)));
        }
        const std::string wrap = node.choice_or("wrap", kWrapNames[0].name, enum_names(kWrapNames));
        const Projection projection = parse_projection(node, "projection", ProjectionKind::Uv);
        const std::filesystem::path file = node.file_path("file");
        node.finish();  // mistakes in the node before the file is read
        return std::make_shared<ImageMapTexture<T>>(load(node, "file", file, space, options), projection,
                                                    enum_value(kWrapNames, wrap));
    }

    // {"texture": file, "space": name, "scale": colour}: an image mapped by uv, repeating, scaled.
    ColourTexturePtr short_form(const SceneNode& node) const {
        const std::filesystem::path file = node.file_path("texture");
        const std::string space = image_colour_space(node);
        const std::optional<Rgb> scale = writes(node, "scale") ? std::optional(node.colour("scale")) : std::nullopt;
        node.finish();
        const ImageLoadOptions options{.content = data_images_ ? ImageContent::Data : ImageContent::Colour,
                                       .mip_levels = true};
        ColourTexturePtr image = std::make_shared<ImageMapTexture<Rgb>>(
            load(node, "texture", file, space, options),
            Projection({.kind = ProjectionKind::Uv}, {.uv = true, .where = node.location(), .field_path = node.path()}),
            WrapMode::Repeat);
        if (!scale) return image;
        return std::make_shared<ScaleTexture<Rgb>>(std::move(image), constant_texture(*scale));
    }

    static std::shared_ptr<const ImageTexture> load(const SceneNode& node, const std::string& key,
                                                    const std::filesystem::path& file, const std::string& space,
                                                    const ImageLoadOptions& options) {
        if (!node.context().colours) node.fail("no colour system available to read \"" + file.string() + "\"");
        try {
            return ImageTexture::load(file, space, *node.context().colours, *node.context().memory, options);
        } catch (const InputError& error) {
            node.fail_at(key, error.what());
        }
    }

    bool data_images_;
};

}  // namespace

ScalarTexturePtr parse_scalar_texture(const SceneNode& parent, const std::string& key, float fallback,
                                      NumberRange range) {
    const auto value = parent.optional_value(key);
    if (!value) return constant_texture(fallback);
    if (value->json().is_number()) return finite_constant(*value, float(value->as_number(range)));
    ScalarTexturePtr texture = TextureParser(false).value<float>(*value, 1);
    if (const auto constant = texture->constant()) {
        if (!range.contains(*constant))
            value->fail("the texture's value " + shortest(*constant) + " is out of range: must be " + range.describe());
        return texture;
    }
    // The range's open ends are excluded: the clamp stops at the nearest float inside.
    const float infinity = std::numeric_limits<float>::infinity();
    float low = float(range.low), high = float(range.high);
    if (range.low_open) low = std::nextafter(low, infinity);
    if (range.high_open) high = std::nextafter(high, -infinity);
    return std::make_shared<ClampTexture<float>>(std::move(texture), Clamp{low, high});
}

ColourTexturePtr parse_colour_texture(const SceneNode& parent, const std::string& key, const Rgb& fallback,
                                      ColourRange range) {
    const auto value = parent.optional_value(key);
    if (!value) return constant_texture(fallback);
    ColourTexturePtr texture = TextureParser(false).value<Rgb>(*value, 1);
    if (range == ColourRange::Any) return texture;
    const bool reflectance = range == ColourRange::Reflectance;
    const float high = reflectance ? 1.0f : float(kMaxEmitted);
    if (const auto c = texture->constant()) {
        if (c->r < 0 || c->g < 0 || c->b < 0 || c->max() > high)
            parent.fail_at(key, reflectance ? "each reflectance component must lie in [0, 1] (energy conservation)"
                                            : "each emitted component must lie in [0, 1e30]");
        return texture;
    }
    return std::make_shared<ClampTexture<Rgb>>(std::move(texture), Clamp{0, high});
}

ColourTexturePtr parse_data_texture(const SceneNode& parent, const std::string& key) {
    const auto value = parent.optional_value(key);
    if (!value) return nullptr;
    return TextureParser(true).value<Rgb>(*value, 1);
}

}  // namespace isotrace
