// Scene plugin "superquadric": one superquadric given inline, or a "superquadrics" list (one Embree primitive
// each), each with its semi-axes, exponents, placement and list of Barr deformations (docs/scene-format.md).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/superquadric/superquadric_shape.h"
#include "renderer/core/input_error.h"
#include "renderer/core/memory_budget.h"
#include "renderer/core/ray.h"
#include "renderer/params/transform_parser.h"

namespace isotrace {
namespace {

constexpr double kDegrees = std::numbers::pi / 180;
constexpr double kMaxTwistDegrees = 3600;  // ten turns end to end

Deformation parse_bend(const SceneNode& bend, const IntervalBox& deformed_so_far) {
    double curvature = bend.number("curvature");
    if (curvature == 0) bend.fail_at("curvature", "must not be 0 (leave the bend out for no bend)");
    double direction = bend.number_or("direction", 0) * kDegrees;
    if (curvature < 0) {  // bending the other way is bending toward the opposite direction
        curvature = -curvature;
        direction += std::numbers::pi;
    }
    const double centre = bend.number_or("center", 0);
    Interval region = deformed_so_far.z;
    if (bend.has("region")) {
        const std::vector<double> r = bend.numbers("region", 2);
        if (!(r[0] < r[1])) bend.fail_at("region", "expected [z_low, z_high] with z_low < z_high");
        region = {r[0], r[1]};
    }
    bend.finish();
    return Bend(curvature, direction, centre, region);
}

// One entry of "deform": {"taper": t | [tx, ty]}, {"twist": degrees} or {"bend": {...}}.
Deformation parse_deformation(const SceneNode& entry, double half_height, const IntervalBox& deformed_so_far) {
    const std::vector<std::string> keys = entry.keys();
    if (keys.size() != 1)
        entry.fail("a deformation is one of {\"taper\": t or [tx, ty]}, {\"twist\": degrees}, {\"bend\": {...}}");
    if (entry.has("taper")) {
        const SceneNode taper = *entry.optional_value("taper");
        if (taper.json().is_number()) {
            const double rate = taper.as_number();
            return Taper(rate, rate, half_height);
        }
        const std::vector<double> rates = entry.numbers("taper", 2);
        return Taper(rates[0], rates[1], half_height);
    }
    // The crossing search subdivides until each cell turns by little: its work grows with the number of turns, so
    // the total twist is bounded (1e9 degrees never finished and ignored Ctrl-C).
    if (entry.has("twist"))
        return Twist(entry.number("twist", NumberRange::between(-kMaxTwistDegrees, kMaxTwistDegrees)) * kDegrees /
                         (2 * half_height),
                     half_height);
    if (entry.has("bend")) return parse_bend(entry.object("bend"), deformed_so_far);
    entry.finish();  // names the unknown key, with a suggestion
    entry.fail("unknown deformation");
}

Superquadric parse_superquadric(const SceneNode& node) {
    Vec3d radii{1, 1, 1};
    if (node.has("radii")) {
        const std::vector<double> r = node.numbers("radii", 3, NumberRange::positive());
        radii = {r[0], r[1], r[2]};
    }
    std::vector<double> exponents{1, 1};
    if (node.has("exponents"))
        exponents = node.numbers("exponents", 2,
                                 NumberRange::between(Superellipsoid::kMinExponent, Superellipsoid::kMaxExponent));
    const Superellipsoid shape(radii, exponents[0], exponents[1]);
    Transform placement = Transform::translate(node.vec3_or("center", {0, 0, 0}));
    if (const auto rotate = node.optional_value("rotate")) placement = placement * parse_rotation(*rotate);

    DeformationChain chain(shape);
    for (const SceneNode& entry : node.object_array("deform")) {
        const Deformation stage = parse_deformation(entry, shape.radii().z, chain.deformed_box());
        entry.finish();
        try {
            chain.append(stage);
        } catch (const std::invalid_argument& error) {
            entry.fail(error.what());
        }
    }
    // A deformed shape's surface shell grows as rays find its blocks: charged at its largest before any is found.
    if (!chain.empty())
        node.charge_at("deform", SurfaceShell::kMostHeapBytes, "the surface shell of a deformed superquadric");
    Superquadric result(shape, std::move(chain), placement);
    const IntervalBox b = result.bounds();
    if (std::max(max_component(abs(b.lower())), max_component(abs(b.upper()))) > kWorldLimit)
        node.fail("superquadric extends beyond 1e18 from the origin");  // Embree silently drops such bounds
    return result;
}

std::unique_ptr<Shape> create(const SceneNode& node) {
    std::vector<Superquadric> superquadrics;
    const std::vector<SceneNode> list = node.object_array("superquadrics");
    // Each superquadric's record (its shell's block table even when undeformed) and its exponents' tables (shared
    // where exponents repeat, so at most) are charged before the list is made: a scene file's short entries would
    // otherwise stand for far more memory than the file's text.
    const std::size_t count = std::max<std::size_t>(1, list.size());
    node.charge_at(list.empty() ? "type" : "superquadrics",
                   saturating_product({count, sizeof(Superquadric) + Superellipsoid::kMostTableBytes}),
                   std::to_string(count) + " superquadric record(s)");
    superquadrics.reserve(count);
    if (!list.empty()) {
        for (const char* key : {"radii", "exponents", "center", "rotate", "deform"})
            if (node.has(key)) node.fail_at(key, "give the fields inside \"superquadrics\" or a single superquadric, not both");
        for (const SceneNode& item : list) {
            superquadrics.push_back(parse_superquadric(item));
            item.finish();
        }
    } else {
        if (node.has("superquadrics")) node.fail_at("superquadrics", "the list of superquadrics is empty");
        superquadrics.push_back(parse_superquadric(node));
    }
    return std::make_unique<SuperquadricShape>(std::move(superquadrics));
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(shape_registry, "superquadric",
                         "superquadric(s) with Barr deformations; radii [a1,a2,a3], exponents [e1 (z), e2 (xy)] in "
                         "[0.02, 4], center, rotate, deform: [{taper}, {twist}, {bend}] or superquadrics: [{...}]",
                         create)

}  // namespace isotrace
