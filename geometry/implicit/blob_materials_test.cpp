// Blob elements with materials of their own: the blend of the parts' shares of the field (exact halves on the
// mid-plane of two equal metaballs, one part near a centre, the four largest of more, weights ≥ 0 adding up to
// exactly 1), hard cubes and the fallback where no share is positive; the shape's parts, shading and field; the
// scene file's "material" keys and their errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "geometry/implicit/blob_group_shape.h"
#include "geometry/implicit/implicit_test_support.h"
#include "geometry/mesh/mesh_test_support.h"
#include "renderer/core/memory_budget.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {
namespace {

using mesh_test::input_error_message;
using mesh_test::ScratchDirectory;

// Parts "" (0) and one named part per entry of `names`.
std::vector<MaterialReference> parts_named(const std::vector<std::string>& names) {
    std::vector<MaterialReference> parts{MaterialReference{}};
    for (const std::string& name : names) parts.push_back({name, {}, ""});
    return parts;
}

BlobGroup group_of(std::vector<Metacube> elements) {
    return BlobGroup(std::move(elements), make_field_function("kim", 4.0), 0.5);
}

MaterialBlend blend_at(const BlobMaterials& materials, const BlobGroup& group, const Vec3d& point) {
    return materials.blend(group, group.cells().elements_near(point), point);
}

// Weights ≥ 0 whose float sum is exactly 1 whichever way round they are added; distinct parts in range.
void expect_valid_blend(const MaterialBlend& blend, std::size_t part_count, const std::string& where) {
    ASSERT_GE(blend.count, 1) << where;
    ASSERT_LE(blend.count, MaterialBlend::kMaxParts) << where;
    float forwards = 0, backwards = 0;
    for (int i = 0; i < blend.count; ++i) {
        EXPECT_GE(blend.weight[std::size_t(i)], 0.0f) << where;
        EXPECT_LT(blend.part[std::size_t(i)], part_count) << where;
        for (int j = 0; j < i; ++j) EXPECT_NE(blend.part[std::size_t(i)], blend.part[std::size_t(j)]) << where;
        forwards += blend.weight[std::size_t(i)];
        backwards += blend.weight[std::size_t(blend.count - 1 - i)];
    }
    EXPECT_EQ(forwards, 1.0f) << where;
    EXPECT_EQ(backwards, 1.0f) << where;
}

float weight_of(const MaterialBlend& blend, std::uint32_t part) {
    for (int i = 0; i < blend.count; ++i)
        if (blend.part[std::size_t(i)] == part) return blend.weight[std::size_t(i)];
    return 0;
}

// Two equal metaballs, "red" (part 1) at x = −0.6 and "blue" (part 2) at x = +0.6.
struct RedAndBlue {
    BlobGroup group = group_of({Metacube::metaball({-0.6, 0, 0}, 1.2, 1.0), Metacube::metaball({0.6, 0, 0}, 1.2, 1.0)});
    BlobMaterials materials{parts_named({"red", "blue"}), {1, 2}};
};

TEST(BlobMaterials, EqualMetaballsShareTheMidPlaneExactlyInHalves) {
    const RedAndBlue pair;
    std::mt19937 random(5);
    std::uniform_real_distribution<double> across(-0.9, 0.9);
    for (int i = 0; i < 200; ++i) {
        const Vec3d point(0, across(random), across(random));
        if (point.y * point.y + point.z * point.z > 0.81) continue;  // both supports reach the disc
        const MaterialBlend blend = blend_at(pair.materials, pair.group, point);
        ASSERT_EQ(blend.count, 2) << i;
        EXPECT_EQ(blend.part[0], 1u) << i;  // equal shares: the lower part first
        EXPECT_EQ(blend.part[1], 2u) << i;
        EXPECT_EQ(blend.weight[0], 0.5f) << i;
        EXPECT_EQ(blend.weight[1], 0.5f) << i;
    }
}

TEST(BlobMaterials, TowardACentreTheBlendTendsToThatElementsPart) {
    const RedAndBlue pair;
    float previous = 0.5f;
    for (int step = 1; step <= 12; ++step) {
        const Vec3d point(-0.05 * step, 0.1, 0);
        const MaterialBlend blend = blend_at(pair.materials, pair.group, point);
        expect_valid_blend(blend, 3, std::to_string(step));
        EXPECT_EQ(blend.part[0], 1u) << step;  // red has the larger share on its side
        const float red = weight_of(blend, 1);
        EXPECT_GT(red, previous) << step;
        previous = red;
    }
    EXPECT_GT(previous, 0.999f);
    // At red's centre blue's support just ends: red alone.
    const MaterialBlend at_centre = blend_at(pair.materials, pair.group, {-0.6, 0, 0});
    ASSERT_EQ(at_centre.count, 1);
    EXPECT_EQ(at_centre.part[0], 1u);
    EXPECT_EQ(at_centre.weight[0], 1.0f);
}

TEST(BlobMaterials, OfMoreThanFourPartsTheFourLargestAreKeptAndRenormalised) {
    // Six metaballs about the origin, each its own part, whose terms at the origin are known: weight k·0.1 at the
    // same distance, so the shares are in proportion to the weights.
    std::vector<Metacube> elements;
    std::vector<std::uint32_t> element_parts;
    const double weights[] = {0.3, 0.9, 0.1, 0.6, 0.5, 0.2};
    for (int k = 0; k < 6; ++k) {
        const double angle = k * 2 * M_PI / 6;
        elements.push_back(Metacube::metaball({0.4 * std::cos(angle), 0.4 * std::sin(angle), 0}, 1.0, weights[k]));
        element_parts.push_back(std::uint32_t(k + 1));
    }
    const BlobGroup group = group_of(elements);
    const BlobMaterials materials(parts_named({"a", "b", "c", "d", "e", "f"}), element_parts);
    const MaterialBlend blend = blend_at(materials, group, {0, 0, 0});
    expect_valid_blend(blend, 7, "origin");
    ASSERT_EQ(blend.count, 4);
    // Largest first: 0.9 (part 2), 0.6 (4), 0.5 (5), 0.3 (1); 0.2 and 0.1 are dropped.
    const std::uint32_t expected_parts[] = {2, 4, 5, 1};
    const double kept = 0.9 + 0.6 + 0.5 + 0.3;
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(blend.part[std::size_t(i)], expected_parts[i]) << i;
        EXPECT_NEAR(blend.weight[std::size_t(i)], weights[expected_parts[i] - 1] / kept, 1e-6) << i;
    }
}

TEST(BlobMaterials, WeightsAreNonNegativeAndSumToExactlyOneEverywhere) {
    // Metaballs, metacubes, hard cubes and carving elements spread over nine parts.
    std::mt19937_64 rng(17);
    std::vector<Metacube> elements;
    std::vector<std::uint32_t> element_parts;
    std::uniform_int_distribution<std::uint32_t> part(0, 8);
    for (int i = 0; i < 80; ++i) {
        if (i % 10 == 0) {
            OrientedBox box;
            box.centre = random_vector(rng, -2, 2);
            box.half_size = {0.3, 0.2, 0.4};
            elements.emplace_back(box, 0.0, 1.0);
        } else {
            elements.push_back(random_metacube(rng));
        }
        element_parts.push_back(part(rng));
    }
    const BlobGroup group = group_of(elements);
    const BlobMaterials materials(parts_named({"a", "b", "c", "d", "e", "f", "g", "h"}), element_parts);
    int many = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3d point = random_vector(rng, -2.5, 2.5);
        if (group.field(point) <= 0) continue;
        const MaterialBlend blend = blend_at(materials, group, point);
        expect_valid_blend(blend, 9, std::to_string(i));
        many += blend.count == MaterialBlend::kMaxParts;
    }
    EXPECT_GT(many, 100);  // the four-part cut is exercised
}

TEST(BlobMaterials, AHardCubeCountsItsWeightOnItsFace) {
    OrientedBox box;
    box.half_size = {0.5, 0.5, 0.5};
    const BlobGroup group = group_of({Metacube(box, 0.0, 1.0), Metacube::metaball({1.0, 0, 0}, 1.0, 0.6)});
    const BlobMaterials materials(parts_named({"cube", "ball"}), {1, 2});
    const double ball = 0.6 * group.kernel().value(0.25, 1.0);
    // On the face x = 0.5 and just either side of it, as rounding puts a hit.
    for (const double x : {0.5, std::nextafter(0.5, 1.0), 0.5 + 1e-9, std::nextafter(0.5, 0.0)}) {
        const MaterialBlend blend = blend_at(materials, group, {x, 0, 0});
        expect_valid_blend(blend, 3, std::to_string(x));
        EXPECT_NEAR(weight_of(blend, 1), 1.0 / (1.0 + ball), 1e-6) << x;
        EXPECT_NEAR(weight_of(blend, 2), ball / (1.0 + ball), 1e-6) << x;
    }
    // Well outside the box only the ball's field is there.
    const MaterialBlend beyond = blend_at(materials, group, {0.6, 0, 0});
    ASSERT_EQ(beyond.count, 1);
    EXPECT_EQ(beyond.part[0], 2u);
}

TEST(BlobMaterials, WhereNoShareIsPositiveTheNearestElementsPartTakesAll) {
    // A carving element (part 1) and a ball (part 2) whose support ends at the point: no positive share.
    const BlobGroup group = group_of({Metacube::metaball({0, 0, 0}, 1.0, -1.0), Metacube::metaball({1.5, 0, 0}, 1.0, 1.0)});
    const BlobMaterials materials(parts_named({"carve", "ball"}), {1, 2});
    const MaterialBlend near_carving = blend_at(materials, group, {0.5, 0, 0});
    ASSERT_EQ(near_carving.count, 1);
    EXPECT_EQ(near_carving.part[0], 1u);
    EXPECT_EQ(near_carving.weight[0], 1.0f);
}

TEST(BlobMaterials, PartsMustBeInRange) {
    EXPECT_THROW(BlobMaterials(parts_named({"a"}), {0, 2}), std::invalid_argument);
    EXPECT_THROW(BlobMaterials({{"named", {}, ""}}, {0}), std::invalid_argument);
    EXPECT_THROW(BlobGroupShape(group_of({Metacube::metaball({0, 0, 0}, 1, 1)}), BlobMaterials(parts_named({"a"}), {1, 1})),
                 std::invalid_argument);
}

TEST(BlobGroupShapeField, ValueIsTheSummedFieldLessTheThresholdAndTheGradientItsDerivative) {
    const BlobGroupShape lone(group_of({Metacube::metaball({0.3, -0.2, 0.1}, 1.5, 0.8)}));
    const double centre_value = 0.8 * lone.group().kernel().value(0, 1.5) - 0.5;
    ASSERT_TRUE(lone.field_value({0.3, -0.2, 0.1}));
    EXPECT_DOUBLE_EQ(*lone.field_value({0.3, -0.2, 0.1}), centre_value);
    EXPECT_GT(centre_value, 0);                            // inside
    EXPECT_DOUBLE_EQ(*lone.field_value({3, 0, 0}), -0.5);  // beyond the support
    const double iso = *lone.group().kernel().iso_radius(1.5, 0.8, 0.5);
    EXPECT_NEAR(*lone.field_value(Vec3d(0.3, -0.2, 0.1) + Vec3d(0, iso, 0)), 0, 1e-12);  // on the surface

    std::mt19937_64 rng(3);
    const BlobGroupShape shape(random_blob_group(40, 11, "wyvill", 7));
    const double h = 1e-6;
    int checked = 0;
    for (int i = 0; i < 400; ++i) {
        const Vec3d p = random_vector(rng, -1.5, 1.5);
        const Vec3d gradient = shape.field_gradient(p);
        Vec3d difference;
        for (int k = 0; k < 3; ++k) {
            Vec3d step(0, 0, 0);
            step[k] = h;
            difference[k] = (*shape.field_value(p + step) - *shape.field_value(p - step)) / (2 * h);
        }
        EXPECT_NEAR(length(gradient - difference), 0, 1e-5 * (1 + length(gradient))) << i;
        checked += length(gradient) > 0;
    }
    EXPECT_GT(checked, 100);
}

// A scene of two equal balls, red (x < 0) and `second_material` (x > 0), and a ball of the object's material above.
std::string red_blue_scene(const std::string& second_material = "blue") {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"grey": {"type": "diffuse"}, "red": {"type": "diffuse"}, "blue": {"type": "diffuse"}},
  "objects": [{"material": "grey", "shape": {"type": "blobs", "elements": [
    {"center": [-0.6, 0, 0], "radius": 1.2, "material": "red"},
    {"center": [0.6, 0, 0], "radius": 1.2, "material": ")" +
           second_material + R"("},
    {"center": [0, 3, 0], "radius": 0.5}]}}]})";
}

TEST(BlobsPluginMaterials, ElementsNameTheirPartsAndHitsBlendThem) {
    ScratchDirectory directory;
    const auto loaded = load_scene(directory.write("scene.json", red_blue_scene()));
    const RenderScene& scene = *loaded->scene;
    const SceneObject& object = scene.objects()[0];
    const std::vector<MaterialReference> parts = object.shape->part_materials();
    ASSERT_EQ(parts.size(), 3u);
    EXPECT_EQ(parts[0].name, "");
    EXPECT_EQ(parts[1].name, "red");
    EXPECT_EQ(parts[2].name, "blue");
    EXPECT_EQ(parts[2].field, "objects[0].shape.elements[1].material");
    const auto shoot = [&](float x, float y) {
        Ray ray;
        ray.origin = {x, y, 5};
        ray.direction = {0, 0, -1};
        return scene.intersect(ray, RayKind::Camera);
    };
    const auto left = shoot(-0.3f, 0.1f), right = shoot(0.3f, 0.1f), top = shoot(0, 3);
    ASSERT_TRUE(left && right && top);
    // Hits show the blend of the parts' materials, its largest share first.
    for (const auto& hit : {left, right, top}) EXPECT_EQ(hit->material, object.blended_material);
    EXPECT_EQ(object.material_of_part(left->blend.part[0]), scene.find_material("red"));
    EXPECT_EQ(object.material_of_part(right->blend.part[0]), scene.find_material("blue"));
    EXPECT_EQ(object.material_of_part(top->blend.part[0]), scene.find_material("grey"));  // the object's

    // The shape's own shading at the hit: the blend, its largest share as the part.
    RTCHit hit{};
    hit.primID = left->primitive_id;
    const LocalShading shading = object.shape->shading(hit, {0, 0, 1}, Vec3d(left->position));
    expect_valid_blend(shading.blend, 3, "left");
    EXPECT_EQ(shading.part, shading.blend.part[0]);
    EXPECT_EQ(shading.part, 1u);
    EXPECT_GT(shading.blend.count, 1);  // blue's field reaches there too
}

TEST(BlobsPluginMaterials, InACsgEachSurfacePointShowsTheLargestShare) {
    ScratchDirectory directory;
    const auto loaded = load_scene(directory.write("scene.json", R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"grey": {"type": "diffuse"}, "red": {"type": "diffuse"}, "blue": {"type": "diffuse"},
                "green": {"type": "diffuse"}},
  "objects": [{"material": "grey", "shape": {"type": "csg", "op": "union", "children": [
    {"shape": {"type": "box", "center": [0, -3, 0], "half_size": [0.5, 0.5, 0.5]}},
    {"material": "green", "shape": {"type": "blobs", "elements": [
      {"center": [-0.6, 0, 0], "radius": 1.2, "material": "red"},
      {"center": [0.6, 0, 0], "radius": 1.2},
      {"center": [0, 3, 0], "radius": 0.5, "material": "blue"}]}}]}}]})"));
    const RenderScene& scene = *loaded->scene;
    const auto material_at = [&](float x, float y) {
        Ray ray;
        ray.origin = {x, y, 5};
        ray.direction = {0, 0, -1};
        const auto hit = scene.intersect(ray, RayKind::Camera);
        return hit ? hit->material : nullptr;
    };
    EXPECT_EQ(material_at(-0.3f, 0.1f), scene.find_material("red"));
    EXPECT_EQ(material_at(0.3f, 0.1f), scene.find_material("green"));  // no material of its own: the child's
    EXPECT_EQ(material_at(0, 3), scene.find_material("blue"));
    EXPECT_EQ(material_at(0, -3), scene.find_material("grey"));
}

TEST(BlobsPluginMaterials, PlainGroupsHaveNoPartsAndNoBlend) {
    const BlobGroupShape plain(group_of({Metacube::metaball({0, 0, 0}, 1, 1)}));
    EXPECT_TRUE(plain.part_materials().empty());
    RTCHit hit{};
    hit.Ng_z = 1;
    const LocalShading shading = plain.shading(hit, {0, 0, 1}, {0, 0, 0.5});
    EXPECT_EQ(shading.blend.count, 0);
    EXPECT_EQ(shading.part, 0u);
}

TEST(BlobsPluginMaterials, AnUnknownElementMaterialIsReportedAtItsName) {
    ScratchDirectory directory;
    const std::string path = directory.write("scene.json", red_blue_scene("bleu"));
    const std::string message = input_error_message([&] { load_scene(path); });
    EXPECT_NE(message.find("scene.json:6:"), std::string::npos) << message;
    EXPECT_NE(message.find("objects[0].shape.elements[1].material"), std::string::npos) << message;
    EXPECT_NE(message.find("unknown material \"bleu\""), std::string::npos) << message;
}

std::string generated_scene(const std::string& materials) {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"grey": {"type": "diffuse"}, "red": {"type": "diffuse"}, "blue": {"type": "diffuse"}},
  "objects": [{"material": "grey", "shape": {"type": "blobs",
    "generate": {"count": 400, "min": [-1, -1, -1], "max": [1, 1, 1], "radius": [0.2, 0.3], "materials": )" +
           materials + "}}}]}";
}

TEST(BlobsPluginMaterials, GeneratedElementsTakeTheListsMaterialsByChance) {
    ScratchDirectory directory;
    const auto loaded = load_scene(directory.write("scene.json", generated_scene(R"(["red", "blue", "red"])")));
    const auto& shape = dynamic_cast<const BlobGroupShape&>(*loaded->scene->objects()[0].shape);
    const std::vector<MaterialReference> parts = shape.part_materials();
    ASSERT_EQ(parts.size(), 3u);  // a name listed twice is one part
    EXPECT_EQ(parts[1].name, "red");
    EXPECT_EQ(parts[1].field, "objects[0].shape.generate.materials[0]");
    const std::vector<std::uint32_t>& element_parts = shape.materials().element_parts();
    ASSERT_EQ(element_parts.size(), 400u);
    int red = 0;
    for (const std::uint32_t part : element_parts) {
        EXPECT_TRUE(part == 1 || part == 2) << part;
        red += part == 1;
    }
    EXPECT_GT(red, 220);  // two entries of three: about 267
    EXPECT_LT(red, 310);
}

TEST(BlobsPluginMaterials, GeneratedElementsAreChargedForTheirPartsWhenTheGroupHasMaterials) {
    // Whether the generator names the materials or an element listed before it does, every element keeps a part.
    ScratchDirectory directory;
    for (const std::string& shape :
         {std::string(R"("generate": {"count": 100000000, "min": [0, 0, 0], "max": [1, 1, 1], "materials": ["red"]})"),
          std::string(R"("elements": [{"center": [0, 0, 0], "radius": 1, "material": "red"}],
                         "generate": {"count": 100000000, "min": [0, 0, 0], "max": [1, 1, 1]})")}) {
        const std::string path = directory.write("scene.json", R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"grey": {"type": "diffuse"}, "red": {"type": "diffuse"}},
  "objects": [{"material": "grey", "shape": {"type": "blobs", )" + shape + "}}]}");
        SceneOverrides overrides;
        overrides.max_memory_bytes = std::uint64_t(8) << 30;
        const std::string message = input_error_message([&] { load_scene(path, overrides); });
        EXPECT_NE(message.find("needs about " + format_bytes(100'000'000 * (BlobGroup::kPeakBytesPerElement + 4))),
                  std::string::npos)
            << message;
    }
}

TEST(BlobsPluginMaterials, GeneratorMaterialsErrorsNameTheirPlace) {
    ScratchDirectory directory;
    std::string message = input_error_message([&] { load_scene(directory.write("a.json", generated_scene(R"(["red", "bleu"])"))); });
    EXPECT_NE(message.find("objects[0].shape.generate.materials[1]"), std::string::npos) << message;
    EXPECT_NE(message.find("unknown material \"bleu\""), std::string::npos) << message;
    message = input_error_message([&] { load_scene(directory.write("b.json", generated_scene("[]"))); });
    EXPECT_NE(message.find("objects[0].shape.generate.materials"), std::string::npos) << message;
    EXPECT_NE(message.find("non-empty list"), std::string::npos) << message;
    message = input_error_message([&] { load_scene(directory.write("c.json", generated_scene("[3]"))); });
    EXPECT_NE(message.find("objects[0].shape.generate.materials[0]"), std::string::npos) << message;
}

}  // namespace
}  // namespace isotrace
