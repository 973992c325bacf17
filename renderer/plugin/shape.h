#pragma once
// Shape: a geometry plugin. It owns its data, builds one Embree geometry, and completes hits with shading
// data. The scene either bakes an object's transform into the shape (when the shape can represent the
// transformed result exactly) or traces the shape in its own space, as a placement.
#include <embree3/rtcore.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/core/input_error.h"
#include "renderer/embree/triangle_hit.h"
#include "renderer/math/transform.h"
#include "renderer/plugin/implicit_field.h"
#include "renderer/plugin/registry.h"
#include "renderer/plugin/surface_hit.h"

namespace isotrace {

// Shading data in the shape's own space (object space when instanced).
struct LocalShading {
    Vec3f geometric_normal;       // unit; the shape's orientation convention (outward / counter-clockwise front)
    Vec3f normal;                 // shading normal, unit length
    std::array<float, 2> uv{0, 0};
    std::uint32_t part = 0;       // composite shapes: the part hit, an index into Shape::part_materials()
    Vec3f dpdu{}, dpdv{};         // derivatives of the point along uv, where the shape has uv (else zero)
    MaterialBlend blend{};        // parts whose materials blend at the hit (Shape::part_materials indices)
};

// The material a part of a composite shape names (a CSG child's "material"), and where the name is written, so
// that the scene loader can resolve it and report an unknown name at its place in the file.
struct MaterialReference {
    std::string name;  // empty: the part has none of its own and shows the object's material
    SourceLocation location;
    std::string field;  // JSON path of the name
};

struct Bounds3f {
    Vec3f lower{1e30f, 1e30f, 1e30f};
    Vec3f upper{-1e30f, -1e30f, -1e30f};
    void extend(const Vec3f& p) {
        lower = min(lower, p);
        upper = max(upper, p);
    }
    bool empty() const { return lower.x > upper.x; }
    // Radius of the sphere around the box (0 when empty): how far lights at infinity must reach.
    float bounding_radius() const { return empty() ? 0.0f : 0.5f * length(upper - lower); }
};

// A point drawn on a shape's surface, for area lights.
struct SurfaceSample {
    Vec3f position;
    Vec3f normal;        // unit geometric normal (the front / outward side)
    float pdf_area = 0;  // density per unit area
};

// A point drawn on a shape's surface as seen from a reference point, for area lights that sample by solid angle.
struct SolidAngleSample {
    Vec3f position;
    Vec3f normal;               // unit geometric normal (the front side)
    float pdf_solid_angle = 0;  // density per unit solid angle at the reference point; 0 = no sample
};

// Shading that Embree's hit alone gives: both normals the geometric one (Embree's Ng, normalised) and Embree's
// barycentric (u, v) as uv, swapped for shapes whose triangles were reversed (see Shape::hit_shading).
inline LocalShading shading_of_embree_hit(const RTCHit& hit, const Vec3f& geometric_normal, bool swap_uv) {
    LocalShading shading;
    shading.geometric_normal = shading.normal = geometric_normal;
    shading.uv = swap_uv ? std::array{hit.v, hit.u} : std::array{hit.u, hit.v};
    return shading;
}

// Whether a shape's shading() is shading_of_embree_hit (and with which uv), so that the scene can complete its
// hits without the call: the path tracer completes one hit per ray, and a virtual call returning its result
// through memory on every one of them shows in a render of flat-shaded triangles (docs/decisions.md, "Hot data is
// written the way it is read").
enum class HitShading { Computed, EmbreeHit, EmbreeHitSwappedUv };

class Shape {
public:
    virtual ~Shape() = default;

    // Name used in statistics tables ("sphere", "triangle_mesh", ...).
    virtual std::string type_name() const = 0;
    // The scene object's name, given before create_geometry, for shapes that keep statistics per object.
    void set_object_name(std::string name) { object_name_ = std::move(name); }
    const std::string& object_name() const { return object_name_; }
    virtual std::size_t primitive_count() const = 0;
    // Memory the shape keeps for rendering, besides what Embree holds (for the build statistics).
    virtual std::size_t memory_bytes() const { return 0; }
    virtual Bounds3f bounds() const = 0;
    // True for user geometries whose callbacks count their intersection tests (see render_counters.h).
    virtual bool counts_intersection_tests() const { return false; }

    // True when bake(to_world) represents the transformed shape exactly.
    virtual bool can_bake(const Transform& to_world) const = 0;
    virtual void bake(const Transform& to_world) = 0;

    // Creates and commits the Embree geometry (called once, after any bake).
    virtual RTCGeometry create_geometry(RTCDevice device) = 0;

    // Area lights: shapes that can draw points uniformly by area over their (baked) surface say so here.
    // Shapes that cannot (implicit surfaces) may still be emissive; they are then found by BSDF sampling only.
    virtual bool supports_surface_sampling() const { return false; }
    virtual SurfaceSample sample_surface(std::array<float, 2> u) const {
        (void)u;
        return {};
    }
    virtual float surface_area() const { return 0; }
    // Area lights by solid angle (optional; e.g. the rectangle, after Ureña, Fajardo and King): a shape that can
    // draw its points uniformly over the solid angle it subtends at a reference point says so here, and its area
    // light then samples it that way. solid_angle_pdf(reference) is the density sample_solid_angle(reference, ·)
    // draws with (uniform, so one number for every point it returns), or 0 where the shape does not sample by
    // solid angle from `reference` (an angle too small to compute, the reference in the surface's plane): the
    // light then samples by area from there. Both decide alike, so a light's sample() and pdf() always agree.
    virtual bool supports_solid_angle_sampling() const { return false; }
    virtual SolidAngleSample sample_solid_angle(const Vec3f& reference, std::array<float, 2> u) const {
        (void)reference, (void)u;
        return {};
    }
    virtual float solid_angle_pdf(const Vec3f& reference) const {
        (void)reference;
        return 0;
    }
    // True for a shape without finite extent (the infinite plane): bounds() is then the finite box it is given to
    // Embree, which reaches the edge of the world (kWorldLimit), and the scene leaves it out of its own extent
    // (RenderScene::bounds(): how far lights at infinity must reach) and out of the check that a transformed
    // shape stays inside the world.
    virtual bool is_unbounded() const { return false; }

    // Completes a hit found by Embree in this shape's space: `geometric_normal` is Embree's Ng normalised and
    // `point` the hit position. Only the accepted hit is completed, so shapes whose normals cost work (implicit
    // surfaces) compute them here instead of for every candidate hit.
    virtual LocalShading shading(const RTCHit& hit, const Vec3f& geometric_normal, const Vec3d& point) const {
        (void)point;
        return shading_of_embree_hit(hit, geometric_normal, false);
    }
    // What shading() is, asked once after any bake: a shape that overrides shading() says EmbreeHit (or
    // EmbreeHitSwappedUv) only when its shading() then returns exactly shading_of_embree_hit.
    virtual HitShading hit_shading() const { return HitShading::Computed; }
    // Shapes traced as Embree's own triangles: their vertices and triangles, after any bake, so that the scene
    // solves each hit's t, u, v and Ng again (triangle_hit.h) before shading() sees it. Empty for other shapes.
    virtual TriangleView embree_triangles() const { return {}; }

    // Composite shapes whose parts may carry their own materials: one entry per part (LocalShading::part).
    // Empty for shapes of one part, which show the object's material.
    virtual std::vector<MaterialReference> part_materials() const { return {}; }

    // Whether hits report LocalShading::blend (parts whose materials blend), rather than one part.
    virtual bool blends_parts() const { return false; }
    // Whether LocalShading::uv is a parametrisation of the surface (meshes with uv, patches, tubes), so that
    // textures may be mapped by it.
    virtual bool has_uv() const { return false; }
    // Implicit shapes: the field whose level set is the surface, in the shape's own space (object space when
    // instanced, world space when baked), positive inside, for textures that read it. nullopt elsewhere.
    virtual std::optional<double> field_value(const Vec3d& point) const {
        (void)point;
        return std::nullopt;
    }
    virtual Vec3d field_gradient(const Vec3d& point) const {
        (void)point;
        return {};
    }
    // Shapes that are implicit surfaces: their field for the polygonisers (implicit_field.h), in the shape's own
    // space; null for shapes that have none. Throws std::invalid_argument when this particular shape has no field
    // (an open mesh, say). The field may refer to the shape: keep the shape alive while the field is used.
    virtual std::unique_ptr<ImplicitField> implicit_field() const { return nullptr; }

private:
    std::string object_name_;
};

Registry<Shape>& shape_registry();

// Shape wrappers: an object key (the registered name, "tessellate") whose settings object turns the object's shape
// into another shape made from it. The scene loader applies every wrapper whose key the object has; the factory
// reads and finishes the settings and fails there.
Registry<Shape, std::unique_ptr<Shape>>& shape_wrapper_registry();

}  // namespace isotrace
