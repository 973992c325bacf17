#include "renderer/plugin/registry.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "renderer/plugin/camera.h"
#include "renderer/plugin/integrator.h"
#include "renderer/plugin/light.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/pixel_filter.h"
#include "renderer/plugin/sampler_registry.h"
#include "renderer/plugin/shape.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

using Scene = testing::ParsedScene;

struct Widget {
    std::string type;
    double size = 0;
    int teeth = 0;
};

// A registry of the test's own, with factories that take an extra argument like the camera registry does.
Registry<Widget, int> make_widget_registry() {
    Registry<Widget, int> registry("widget");
    registry.add(
        "gear",
        [](const SceneNode& node, int teeth) {
            auto widget = std::make_unique<Widget>();
            widget->type = "gear";
            widget->size = node.number_or("size", 1.0, NumberRange::positive());
            widget->teeth = teeth;
            return widget;
        },
        "a toothed wheel; size");
    registry.add(
        "spring",
        [](const SceneNode& node, int) {
            auto widget = std::make_unique<Widget>();
            widget->type = "spring";
            widget->size = node.number("stiffness");
            return widget;
        },
        "a coil; stiffness");
    registry.add(
        "sprocket", [](const SceneNode&, int) { return std::make_unique<Widget>(); }, "a chain wheel");
    return registry;
}

void expect_error(const std::function<void()>& action, int line, int column, const std::string& field,
                  const std::string& message) {
    testing::expect_input_error(action, "scene.json", line, column, field, message);
}

TEST(Registry, CreatesByTypeAndPassesArguments) {
    const Registry<Widget, int> widgets = make_widget_registry();
    const Scene scene(R"({"type": "gear", "size": 2.5})");
    const std::unique_ptr<Widget> gear = widgets.create(scene.root(), 12);
    ASSERT_NE(gear, nullptr);
    EXPECT_EQ(gear->type, "gear");
    EXPECT_EQ(gear->size, 2.5);
    EXPECT_EQ(gear->teeth, 12);
    const Scene spring(R"({"type": "spring", "stiffness": 40})");
    EXPECT_EQ(widgets.create(spring.root(), 0)->type, "spring");
}

TEST(Registry, DescribesItsEntries) {
    const Registry<Widget, int> widgets = make_widget_registry();
    EXPECT_EQ(widgets.kind(), "widget");
    EXPECT_EQ(widgets.types(), (std::vector<std::string>{"gear", "spring", "sprocket"}));  // sorted
    EXPECT_TRUE(widgets.contains("gear"));
    EXPECT_FALSE(widgets.contains("Gear"));
    EXPECT_EQ(widgets.entries().at("spring").summary, "a coil; stiffness");
}

TEST(Registry, UnknownTypeListsTheAvailableTypesAndPointsAtTheTypeValue) {
    const Registry<Widget, int> widgets = make_widget_registry();
    const Scene scene(
        "{\n"
        "  \"size\": 2,\n"
        "  \"type\": \"gaer\"\n"
        "}");
    expect_error([&] { widgets.create(scene.root(), 0); }, 3, 11, "type",
                 "scene.json:3:11: type: unknown widget type \"gaer\" (did you mean \"gear\"?); "
                 "available: gear, spring, sprocket");
    const Scene far(R"({"type": "lever"})");
    expect_error([&] { widgets.create(far.root(), 0); }, 1, 10, "type",
                 "scene.json:1:10: type: unknown widget type \"lever\"; available: gear, spring, sprocket");
}

TEST(Registry, PathsOfNestedNodesAppearInErrors) {
    const Registry<Widget, int> widgets = make_widget_registry();
    const Scene scene(R"({"parts": [{"type": "gear"}, {"type": "sprokcet"}]})");
    const std::vector<SceneNode> parts = scene.root().object_array("parts");
    EXPECT_NO_THROW(widgets.create(parts[0], 0));
    expect_error([&] { widgets.create(parts[1], 0); }, 1, 39, "parts[1].type",
                 "scene.json:1:39: parts[1].type: unknown widget type \"sprokcet\" (did you mean \"sprocket\"?); "
                 "available: gear, spring, sprocket");
}

TEST(Registry, TypeIsRequiredWithoutADefault) {
    const Registry<Widget, int> widgets = make_widget_registry();
    const Scene scene(R"({"size": 2})");
    expect_error([&] { widgets.create(scene.root(), 0); }, 1, 1, "", "scene.json:1:1: missing required field \"type\"");
    const Scene number(R"({"type": 3})");
    expect_error([&] { widgets.create(number.root(), 0); }, 1, 10, "type",
                 "scene.json:1:10: type: expected a string, found number");
}

TEST(Registry, DefaultTypeIsUsedOnlyWhenTypeIsAbsent) {
    const Registry<Widget, int> widgets = make_widget_registry();
    const Scene absent(R"({"size": 3})");
    const auto widget = widgets.create(absent.root(), 5, "gear");
    EXPECT_EQ(widget->type, "gear");
    EXPECT_EQ(widget->size, 3);
    EXPECT_EQ(widget->teeth, 5);
    const Scene given(R"({"type": "sprocket"})");
    EXPECT_EQ(widgets.create(given.root(), 0, "gear")->type, "");  // the sprocket factory sets no type name
    const Scene unknown(R"({"type": "cog"})");
    EXPECT_THROW(widgets.create(unknown.root(), 0, "gear"), InputError);
}

TEST(Registry, FinishRunsAfterTheFactoryAndRejectsUnknownKeys) {
    const Registry<Widget, int> widgets = make_widget_registry();
    // "size" is read only inside the factory: finish() must come after it to accept the key.
    const Scene good(R"({"type": "gear", "size": 2})");
    EXPECT_NO_THROW(widgets.create(good.root(), 0));
    const Scene typo(R"({"type": "gear", "szie": 2})");
    expect_error([&] { widgets.create(typo.root(), 0); }, 1, 26, "szie",
                 "scene.json:1:26: szie: unknown key \"szie\" (did you mean \"size\"?); known keys here: size, type");
    // Keys of another type are unknown to this one.
    const Scene other(R"({"type": "gear", "stiffness": 2})");
    expect_error([&] { widgets.create(other.root(), 0); }, 1, 31, "stiffness",
                 "scene.json:1:31: stiffness: unknown key \"stiffness\"; known keys here: size, type");
}

TEST(Registry, FactoryErrorsComeBeforeUnknownKeys) {
    const Registry<Widget, int> widgets = make_widget_registry();
    const Scene scene(R"({"type": "gear", "size": -1, "colour": 2})");
    expect_error([&] { widgets.create(scene.root(), 0); }, 1, 26, "size",
                 "scene.json:1:26: size: value -1 out of range: must be > 0");
}

// The registration macro, used as plugin files use it.
Registry<Widget>& test_widget_registry() {
    static Registry<Widget> registry("test widget");
    return registry;
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(test_widget_registry, "knob", "a registered knob",
                         [](const SceneNode&) -> std::unique_ptr<Widget> {
                             auto widget = std::make_unique<Widget>();
                             widget->type = "knob";
                             return widget;
                         })

namespace {

TEST(Registry, MacroRegistersAtLoadTime) {
    ASSERT_TRUE(test_widget_registry().contains("knob"));
    EXPECT_EQ(test_widget_registry().entries().at("knob").summary, "a registered knob");
    const Scene scene(R"({"type": "knob"})");
    EXPECT_EQ(test_widget_registry().create(scene.root())->type, "knob");
}

// --- The registries of the library ---------------------------------------------------------------

template <class R>
void expect_types(const R& registry, const std::vector<std::string>& expected) {
    for (const std::string& type : expected) {
        EXPECT_TRUE(registry.contains(type)) << registry.kind() << " registry lacks \"" << type << "\"";
        if (registry.contains(type)) {
            EXPECT_FALSE(registry.entries().at(type).summary.empty()) << type;
        }
    }
}

TEST(BuiltInRegistries, ContainTheBuiltInPlugins) {
    expect_types(shape_registry(), {"sphere", "mesh"});
    expect_types(camera_registry(), {"perspective", "orthographic"});
    expect_types(pixel_filter_registry(), {"box", "gaussian", "blackman_harris"});
    expect_types(sampler_registry(), {"sobol", "independent"});
    expect_types(integrator_registry(), {"preview"});
    expect_types(material_registry(), {"diffuse", "emissive"});
    expect_types(light_registry(), {"directional", "point"});
}

TEST(BuiltInRegistries, KindsNameTheirPlugins) {
    EXPECT_EQ(shape_registry().kind(), "shape");
    EXPECT_EQ(camera_registry().kind(), "camera");
    EXPECT_EQ(pixel_filter_registry().kind(), "pixel filter");
    EXPECT_EQ(sampler_registry().kind(), "sampler");
    EXPECT_EQ(integrator_registry().kind(), "integrator");
    EXPECT_EQ(material_registry().kind(), "material");
    EXPECT_EQ(light_registry().kind(), "light");
}

TEST(BuiltInRegistries, CreateARealShapeAndSuggestAMisspelledOne) {
    const Scene sphere(R"({"type": "sphere", "center": [1, 2, 3], "radius": 0.5})");
    const std::unique_ptr<Shape> shape = shape_registry().create(sphere.root());
    EXPECT_EQ(shape->type_name(), "sphere");
    EXPECT_EQ(shape->primitive_count(), 1u);
    const Bounds3f bounds = shape->bounds();
    EXPECT_NEAR(bounds.lower.x, 0.5f, 1e-6f);
    EXPECT_NEAR(bounds.upper.z, 3.5f, 1e-6f);

    const Scene typo(R"({"type": "spehre"})");
    try {
        shape_registry().create(typo.root());
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind("scene.json:1:10: type: unknown shape type \"spehre\" (did you mean \"sphere\"?); "
                                "available: ",
                                0),
                  0u)
            << message;
    }
}

}  // namespace
}  // namespace isotrace
