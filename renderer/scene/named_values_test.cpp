#include "renderer/scene/named_values.h"

#include <gtest/gtest.h>

#include "renderer/core/memory_budget.h"
#include "tests/support/input_error_of.h"

namespace isotrace {
namespace {

JsonValue substituted(const std::string& text, std::uint64_t memory_limit = std::uint64_t(1) << 30) {
    JsonValue document = parse_json(text, "scene.json");
    MemoryBudget memory(memory_limit);
    substitute_named_values(document, memory);
    return document;
}

InputError error_of(const std::string& text, std::uint64_t memory_limit = std::uint64_t(1) << 30) {
    return testing::input_error_of([&] { substituted(text, memory_limit); }, text);
}

TEST(NamedValues, ReferencesBecomeCopiesOfTheirValues) {
    const JsonValue document = substituted(R"({
  "values": {"roughness": 0.2, "tint": [0.8, 0.1, 0.1]},
  "materials": {"a": {"roughness": {"$value": "roughness"}, "base_colour": {"$value": "tint"}},
                "b": {"roughness": {"$value": "roughness"}}}
})");
    EXPECT_EQ(document.find("values"), nullptr);
    const JsonValue& a = *document.find("materials")->find("a");
    EXPECT_EQ(a.find("roughness")->number, 0.2);
    ASSERT_EQ(a.find("base_colour")->items.size(), 3u);
    EXPECT_EQ(a.find("base_colour")->items[0].number, 0.8);
    EXPECT_EQ(document.find("materials")->find("b")->find("roughness")->number, 0.2);
    // A copy is located where its value is written.
    EXPECT_EQ(a.find("roughness")->location.line, 2);
    EXPECT_EQ(a.find("roughness")->location.column, 27);
}

TEST(NamedValues, WithoutReferencesNothingChanges) {
    const JsonValue document = substituted(R"({"film": {"spp": 4}, "objects": [{"name": "$value"}]})");
    EXPECT_EQ(document.find("film")->find("spp")->number, 4);
    EXPECT_EQ(document.find("objects")->items[0].find("name")->string, "$value");
}

TEST(NamedValues, UnknownNamesGetASuggestion) {
    const InputError error = error_of(R"({"values": {"roughness": 0.2},
 "materials": {"a": {"roughness": {"$value": "rougness"}}}})");
    EXPECT_EQ(std::string(error.what()),
              "scene.json:2:46: materials.a.roughness: unknown value \"rougness\" (did you mean \"roughness\"?); "
              "defined: roughness");
    EXPECT_EQ(error_of(R"({"film": {"spp": {"$value": "spp"}}})").problem(),
              "unknown value \"spp\"; the scene defines no \"values\"");
}

TEST(NamedValues, MalformedReferencesAndSections) {
    EXPECT_EQ(error_of(R"({"values": {"a": 1}, "x": [{"$value": "a", "b": 2}]})").problem(),
              "a reference to a named value is {\"$value\": \"NAME\"}, with nothing else in the object");
    EXPECT_EQ(error_of(R"({"values": {"a": 1}, "x": {"$value": 3}})").field(), "x");
    EXPECT_EQ(error_of(R"({"values": [1]})").problem(), "expected an object of named values, found array");
    const InputError nested = error_of(R"({"values": {"a": 1, "b": {"$value": "a"}}})");
    EXPECT_EQ(nested.field(), "values.b");
    EXPECT_EQ(nested.problem(), "a named value cannot refer to another named value");
}

TEST(NamedValues, CopiesAreChargedToTheMemoryBudget) {
    std::string big = "[0";
    for (int i = 0; i < 10000; ++i) big += ", 0";
    std::string text = R"({"values": {"big": )" + big + R"(]}, "x": [)";
    for (int i = 0; i < 100; ++i) text += std::string(i ? ", " : "") + R"({"$value": "big"})";
    const InputError error = error_of(text + "]}", std::uint64_t(16) << 20);
    EXPECT_NE(error.problem().find("a copy of the value \"big\""), std::string::npos) << error.what();
}

}  // namespace
}  // namespace isotrace
