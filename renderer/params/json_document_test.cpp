#include "renderer/params/json_document.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <string>

#include "renderer/core/memory_budget.h"
#include "tests/support/scene_files.h"

namespace isotrace {
namespace {

JsonValue parse(const std::string& text) { return parse_json(text, "test.json"); }

// Parses `text`, which must fail, and returns the error for inspection.
InputError parse_error(const std::string& text) {
    try {
        parse(text);
    } catch (const InputError& error) {
        return error;
    }
    ADD_FAILURE() << "parsed without error: " << text;
    return InputError({}, "", "");
}

void expect_error_at(const std::string& text, int line, int column, const std::string& message) {
    const InputError error = parse_error(text);
    EXPECT_EQ(error.location().file, "test.json") << text;
    EXPECT_EQ(error.location().line, line) << text << "\n" << error.what();
    EXPECT_EQ(error.location().column, column) << text << "\n" << error.what();
    EXPECT_EQ(std::string(error.what()), message) << text;
}

void expect_location(const JsonValue& value, int line, int column) {
    EXPECT_EQ(value.location.file, "test.json");
    EXPECT_EQ(value.location.line, line);
    EXPECT_EQ(value.location.column, column);
}

// --- Values --------------------------------------------------------------------------------------

TEST(ParseJson, Literals) {
    EXPECT_TRUE(parse("null").is_null());
    const JsonValue t = parse("true");
    ASSERT_TRUE(t.is_bool());
    EXPECT_TRUE(t.boolean);
    const JsonValue f = parse(" false ");
    ASSERT_TRUE(f.is_bool());
    EXPECT_FALSE(f.boolean);
}

TEST(ParseJson, Numbers) {
    const JsonValue v = parse("[0, -0, 42, -17, 3.25, 1e3, 1E-2, 2.5e+2, -0.5, 123456789012345]");
    ASSERT_TRUE(v.is_array());
    const double expected[] = {0, -0.0, 42, -17, 3.25, 1000, 0.01, 250, -0.5, 123456789012345.0};
    ASSERT_EQ(v.items.size(), std::size(expected));
    for (std::size_t i = 0; i < v.items.size(); ++i) {
        ASSERT_TRUE(v.items[i].is_number()) << i;
        EXPECT_EQ(v.items[i].number, expected[i]) << i;
    }
    EXPECT_TRUE(std::signbit(v.items[1].number));
    // Correctly rounded, not accumulated digit by digit.
    EXPECT_EQ(parse("0.1").number, 0.1);
    EXPECT_EQ(parse("1.7976931348623157e308").number, 1.7976931348623157e308);
}

TEST(ParseJson, StringsAndSimpleEscapes) {
    EXPECT_EQ(parse(R"("plain")").string, "plain");
    EXPECT_EQ(parse(R"("")").string, "");
    EXPECT_EQ(parse(R"("q\" b\\ s\/ \b\f\n\r\t")").string, "q\" b\\ s/ \b\f\n\r\t");
    // UTF-8 passes through untouched.
    EXPECT_EQ(parse("\"Rückseite ✓\"").string, "Rückseite ✓");
}

TEST(ParseJson, UnicodeEscapesBecomeUtf8) {
    EXPECT_EQ(parse(R"("\u0041")").string, "A");
    EXPECT_EQ(parse(R"("\u00e9\u00E9")").string, "\xC3\xA9\xC3\xA9");  // é, either hex case
    EXPECT_EQ(parse(R"("\u20AC")").string, "\xE2\x82\xAC");              // €
    EXPECT_EQ(parse(R"("\uFFFF")").string, "\xEF\xBF\xBF");
    EXPECT_EQ(parse(R"("a\u0000b")").string, std::string("a\0b", 3));
}

TEST(ParseJson, SurrogatePairsBecomeOneCodePoint) {
    EXPECT_EQ(parse(R"("\uD83D\uDE00")").string, "\xF0\x9F\x98\x80");  // U+1F600
    EXPECT_EQ(parse(R"("\uD800\uDC00")").string, "\xF0\x90\x80\x80");  // U+10000
    EXPECT_EQ(parse(R"("\uDBFF\uDFFF")").string, "\xF4\x8F\xBF\xBF");  // U+10FFFF
}

TEST(ParseJson, ArraysAndObjectsKeepFileOrder) {
    const JsonValue v = parse(R"({"z": [1, "two", null, [], {}], "a": true, "m": {"k": false}})");
    ASSERT_TRUE(v.is_object());
    ASSERT_EQ(v.members.size(), 3u);
    EXPECT_EQ(v.members[0].first, "z");
    EXPECT_EQ(v.members[1].first, "a");
    EXPECT_EQ(v.members[2].first, "m");
    const JsonValue* z = v.find("z");
    ASSERT_NE(z, nullptr);
    ASSERT_EQ(z->items.size(), 5u);
    EXPECT_EQ(z->items[0].number, 1);
    EXPECT_EQ(z->items[1].string, "two");
    EXPECT_TRUE(z->items[2].is_null());
    EXPECT_TRUE(z->items[3].is_array());
    EXPECT_TRUE(z->items[3].items.empty());
    EXPECT_TRUE(z->items[4].is_object());
    EXPECT_TRUE(z->items[4].members.empty());
    ASSERT_NE(v.find("m"), nullptr);
    EXPECT_FALSE(v.find("m")->find("k")->boolean);
    EXPECT_EQ(v.find("missing"), nullptr);
    EXPECT_EQ(z->find("z"), nullptr);  // not an object
}

// --- Comments and trailing commas -------------------------------------------------------------------

TEST(ParseJson, TrailingCommasAreAllowed) {
    const JsonValue v = parse("{\"a\": [1, 2,], \"b\": {\"c\": 3,},\n}");
    ASSERT_TRUE(v.is_object());
    ASSERT_EQ(v.members.size(), 2u);
    EXPECT_EQ(v.find("a")->items.size(), 2u);
    EXPECT_EQ(v.find("b")->members.size(), 1u);
    EXPECT_EQ(parse("[1 , ]").items.size(), 1u);
    EXPECT_EQ(parse("[[],\n // last\n]").items.size(), 1u);
}

TEST(ParseJson, CommentsAreSkippedAndPositionsStayExact) {
    const JsonValue v = parse("// a scene\n"
                              "{ /* first */ \"a\": 1, // one\n"
                              "  /* several\n     lines */ \"b\": [2, /* x */ 3],\n"
                              "  \"c\": \"// not a comment /* either */\"\n"
                              "} // end");
    ASSERT_TRUE(v.is_object());
    expect_location(v, 2, 1);
    expect_location(*v.find("a"), 2, 20);
    expect_location(*v.find("b"), 4, 20);
    expect_location(v.find("b")->items[0], 4, 21);
    expect_location(v.find("b")->items[1], 4, 32);
    EXPECT_EQ(v.find("c")->string, "// not a comment /* either */");
    expect_location(*v.find("c"), 5, 8);
}

TEST(ParseJson, ErrorsAfterCommentsHaveExactPositions) {
    expect_error_at("/* a\n b */ {\"a\": // c\n tru}", 3, 2, "test.json:3:2: expected a JSON value but found 't'");
    expect_error_at("// only a comment", 1, 18, "test.json:1:18: expected a JSON value but the file ended");
}

TEST(ParseJson, KindNames) {
    EXPECT_STREQ(JsonValue::kind_name(JsonValue::Kind::Null), "null");
    EXPECT_STREQ(JsonValue::kind_name(JsonValue::Kind::Bool), "boolean");
    EXPECT_STREQ(JsonValue::kind_name(JsonValue::Kind::Number), "number");
    EXPECT_STREQ(JsonValue::kind_name(JsonValue::Kind::String), "string");
    EXPECT_STREQ(JsonValue::kind_name(JsonValue::Kind::Array), "array");
    EXPECT_STREQ(JsonValue::kind_name(JsonValue::Kind::Object), "object");
}

TEST(ParseJson, AllWhitespaceKindsAreSkipped) {
    const JsonValue v = parse(" \t\r\n[ \t1\r\n, 2 ]\r\n ");
    ASSERT_EQ(v.items.size(), 2u);
    EXPECT_EQ(v.items[1].number, 2);
}

TEST(ParseJson, IgnoresAUtf8ByteOrderMark) {
    const JsonValue v = parse("\xEF\xBB\xBF{\"a\": 1}");
    ASSERT_TRUE(v.is_object());
    expect_location(v, 1, 1);
    expect_location(*v.find("a"), 1, 7);
}

// --- Positions -----------------------------------------------------------------------------------

TEST(ParseJson, EveryValueKnowsWhereItStarts) {
    const std::string text =
        "{\n"                          // line 1
        "  \"camera\": {\n"            // line 2: object at column 13
        "    \"fov\": 39.5,\n"         // line 3: number at column 12
        "    \"eye\": [0, -1.5, 2]\n"  // line 4: array at 12, items at 13, 16, 22
        "  },\n"                       //
        "\t\"name\": \"box\", \"on\": true, \"n\": null\n"  // line 6, tab counts as one column
        "}";
    const JsonValue root = parse(text);
    expect_location(root, 1, 1);
    const JsonValue& camera = *root.find("camera");
    expect_location(camera, 2, 13);
    expect_location(*camera.find("fov"), 3, 12);
    const JsonValue& eye = *camera.find("eye");
    expect_location(eye, 4, 12);
    expect_location(eye.items[0], 4, 13);
    expect_location(eye.items[1], 4, 16);
    expect_location(eye.items[2], 4, 22);
    expect_location(*root.find("name"), 6, 10);
    expect_location(*root.find("on"), 6, 23);
    expect_location(*root.find("n"), 6, 34);
}

TEST(ParseJson, CrLfLineEndingsCountOneLineEach) {
    const JsonValue root = parse("{\r\n\"a\": 1,\r\n\r\n  \"b\": 2}");
    expect_location(*root.find("a"), 2, 6);
    expect_location(*root.find("b"), 4, 8);
}

TEST(ParseJson, PositionsFollowMultiLineStrings) {
    // An escaped "\n" inside a string does not start a new line of the file.
    const JsonValue root = parse("{\"a\": \"x\\ny\",\n \"b\": 5}");
    expect_location(*root.find("b"), 2, 7);
}

// --- Errors --------------------------------------------------------------------------------------

TEST(ParseJsonErrors, UnterminatedStringIsReportedWhereItStarts) {
    expect_error_at("{\n  \"name\": \"box", 2, 11, "test.json:2:11: unterminated string (missing closing '\"')");
    expect_error_at("{\n  \"name\": \"box,\n  \"x\": 1\n}", 2, 11,
                    "test.json:2:11: unterminated string (line break before the closing '\"')");
    expect_error_at("\"abc\\", 1, 1, "test.json:1:1: unterminated string (missing closing '\"')");
}

TEST(ParseJsonErrors, ACommaNeedsAnElementBeforeIt) {
    expect_error_at("[,]", 1, 2, "test.json:1:2: expected a JSON value but found ','");
    expect_error_at("[1,,]", 1, 4, "test.json:1:4: expected a JSON value but found ','");
    expect_error_at("{,}", 1, 2, "test.json:1:2: expected a quoted key but found ','");
    expect_error_at("{\"a\": 1,,}", 1, 9, "test.json:1:9: expected a quoted key but found ','");
}

TEST(ParseJsonErrors, UnterminatedBlockCommentIsReportedWhereItStarts) {
    expect_error_at("{\n  /* note\n \"a\": 1 }", 2, 3, "test.json:2:3: unterminated comment (missing closing '*/')");
    expect_error_at("[1] /*", 1, 5, "test.json:1:5: unterminated comment (missing closing '*/')");
    expect_error_at("[1] /*/", 1, 5, "test.json:1:5: unterminated comment (missing closing '*/')");
}

TEST(ParseJsonErrors, ASlashThatStartsNoCommentIsNotJson) {
    expect_error_at("[1, / 2]", 1, 5, "test.json:1:5: expected a JSON value but found '/'");
    expect_error_at("[1] /", 1, 5, "test.json:1:5: unexpected text after the end of the JSON document");
}

TEST(ParseJsonErrors, MissingColonOrComma) {
    expect_error_at("{\"a\" 1}", 1, 6, "test.json:1:6: expected ':' after the key but found '1'");
    expect_error_at("{\"a\": 1 \"b\": 2}", 1, 9, "test.json:1:9: expected ',' or '}' but found '\"'");
    expect_error_at("[1 2]", 1, 4, "test.json:1:4: expected ',' or ']' but found '2'");
    expect_error_at("{a: 1}", 1, 2, "test.json:1:2: expected a quoted key but found 'a'");
}

TEST(ParseJsonErrors, DocumentEndsEarly) {
    expect_error_at("", 1, 1, "test.json:1:1: expected a JSON value but the file ended");
    expect_error_at("  \n ", 2, 2, "test.json:2:2: expected a JSON value but the file ended");
    expect_error_at("[1,\n", 2, 1, "test.json:2:1: expected a JSON value but the file ended");
    expect_error_at("{\"a\": [1]", 1, 10, "test.json:1:10: expected ',' or '}' but the file ended");
}

TEST(ParseJsonErrors, MalformedNumbers) {
    expect_error_at("[01]", 1, 2, "test.json:1:2: malformed number: leading zeros are not allowed");
    expect_error_at("-007", 1, 1, "test.json:1:1: malformed number: leading zeros are not allowed");
    expect_error_at("[1.]", 1, 4, "test.json:1:4: malformed number: digit expected after '.'");
    expect_error_at("[.5]", 1, 2, "test.json:1:2: expected a JSON value but found '.'");
    expect_error_at("[1e]", 1, 4, "test.json:1:4: malformed number: digit expected in exponent");
    expect_error_at("[1e+]", 1, 5, "test.json:1:5: malformed number: digit expected in exponent");
    expect_error_at("[-]", 1, 3, "test.json:1:3: malformed number");
    expect_error_at("[+1]", 1, 2, "test.json:1:2: expected a JSON value but found '+'");
    expect_error_at("[0x10]", 1, 3, "test.json:1:3: expected ',' or ']' but found 'x'");
}

TEST(ParseJsonErrors, NanAndInfinityAreNotJson) {
    expect_error_at("[NaN]", 1, 2, "test.json:1:2: expected a JSON value but found 'N'");
    expect_error_at("[Infinity]", 1, 2, "test.json:1:2: expected a JSON value but found 'I'");
    expect_error_at("[-Infinity]", 1, 3, "test.json:1:3: malformed number");
    expect_error_at("[nan]", 1, 2, "test.json:1:2: expected a JSON value but found 'n'");
}

TEST(ParseJsonErrors, NumberOutOfRangePointsAtTheNumber) {
    expect_error_at("{\n  \"r\": 1e999}", 2, 8, "test.json:2:8: number out of range");
    expect_error_at("[1, -2.5e400]", 1, 5, "test.json:1:5: number out of range");
}

TEST(ParseJsonErrors, DuplicateKeyPointsAtTheSecondKey) {
    const InputError error = parse_error("{\n  \"radius\": 1,\n  \"radius\": 2\n}");
    EXPECT_EQ(error.location().line, 3);
    EXPECT_EQ(error.location().column, 3);
    EXPECT_EQ(error.field(), "radius");
    EXPECT_STREQ(error.what(), "test.json:3:3: radius: duplicate key");
    // Same key in different objects is fine.
    EXPECT_NO_THROW(parse(R"({"a": {"k": 1}, "b": {"k": 2}})"));
}

TEST(ParseJsonErrors, TextAfterTheDocument) {
    expect_error_at("{}\n  x", 2, 3, "test.json:2:3: unexpected text after the end of the JSON document");
    expect_error_at("1 2", 1, 3, "test.json:1:3: unexpected text after the end of the JSON document");
    expect_error_at("truex", 1, 5, "test.json:1:5: unexpected text after the end of the JSON document");
    expect_error_at("{} {}", 1, 4, "test.json:1:4: unexpected text after the end of the JSON document");
}

TEST(ParseJsonErrors, MisspelledLiterals) {
    expect_error_at("[tru]", 1, 2, "test.json:1:2: expected a JSON value but found 't'");
    expect_error_at("[True]", 1, 2, "test.json:1:2: expected a JSON value but found 'T'");
    expect_error_at("['a']", 1, 2, "test.json:1:2: expected a JSON value but found '''");
}

TEST(ParseJsonErrors, NestingLimitIs256ArraysOrObjects) {
    const auto nested = [](int levels) { return std::string(levels, '[') + std::string(levels, ']'); };
    EXPECT_NO_THROW(parse(nested(256)));
    EXPECT_NO_THROW(parse(std::string(256, '[') + "1" + std::string(256, ']')));  // scalars do not count
    expect_error_at(nested(257), 1, 257, "test.json:1:257: JSON nested too deeply (more than 256 arrays/objects)");
    // Far deeper input is rejected, not a stack overflow.
    EXPECT_THROW(parse(nested(100000)), InputError);
    std::string objects;
    for (int i = 0; i < 300; ++i) objects += "{\"k\":";
    EXPECT_THROW(parse(objects + "1" + std::string(300, '}')), InputError);
}

TEST(ParseJsonErrors, ControlCharactersInStrings) {
    expect_error_at("[\"a\tb\"]", 1, 4, "test.json:1:4: control character in string (use an escape)");
    expect_error_at(std::string("[\"a\0b\"]", 7), 1, 4, "test.json:1:4: control character in string (use an escape)");
    expect_error_at("[\"\x1F\"]", 1, 3, "test.json:1:3: control character in string (use an escape)");
    EXPECT_EQ(parse("\"\x7F\"").string, "\x7F");  // DEL is not a control character for JSON
}

TEST(ParseJsonErrors, BadEscapesPointAtTheBackslash) {
    expect_error_at(R"(["ab\x"])", 1, 5, "test.json:1:5: invalid escape '\\x'");
    expect_error_at(R"(["\'"])", 1, 3, "test.json:1:3: invalid escape '\\''");
    expect_error_at(R"(["\u12G4"])", 1, 7, "test.json:1:7: malformed \\u escape");
    expect_error_at(R"(["\u12"])", 1, 7, "test.json:1:7: malformed \\u escape");
}

TEST(ParseJsonErrors, UnpairedSurrogates) {
    expect_error_at(R"(["x\uD83D"])", 1, 4, "test.json:1:4: unpaired surrogate in \\u escape");
    expect_error_at(R"(["\uD83Dx"])", 1, 3, "test.json:1:3: unpaired surrogate in \\u escape");
    expect_error_at(R"(["\uD83D\u0041"])", 1, 3, "test.json:1:3: invalid low surrogate in \\u escape");
    // A low surrogate on its own would become invalid UTF-8 (CESU-8).
    expect_error_at(R"(["ab\uDE00"])", 1, 5, "test.json:1:5: unpaired surrogate in \\u escape");
}

// --- Files ---------------------------------------------------------------------------------------

TEST(ParseJsonFile, ReadsAFileAndNamesItInPositions) {
    testing::TemporaryDirectory dir("json");
    const std::string path = dir.write("scene.json", "{\n  \"a\": [1, 2]\n}\n").string();
    const JsonValue root = parse_json_file(path);
    EXPECT_EQ(root.find("a")->items[1].location.file, path);
    EXPECT_EQ(root.find("a")->items[1].location.line, 2);
    EXPECT_EQ(root.find("a")->items[1].location.column, 12);

    const std::string bad = dir.write("bad.json", "{\n  \"a\": [1, 2,,]\n}\n").string();
    try {
        parse_json_file(bad);
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()), bad + ":2:14: expected a JSON value but found ','");
    }
}

TEST(ParseJsonFile, MissingFileNamesTheFile) {
    testing::TemporaryDirectory dir("json");
    const std::string path = (dir / "no_such_scene.json").string();
    try {
        parse_json_file(path);
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.location().file, path);
        EXPECT_EQ(error.location().line, 0);
        EXPECT_EQ(std::string(error.what()), path + ": file not found");
    }
}

TEST(ParseJsonFile, DirectoryIsNotAFile) {
    testing::TemporaryDirectory dir("json");
    try {
        parse_json_file(dir.path().string());
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  dir.path().string() + ": is a directory, not a regular file (isotrace reads only regular files)");
    }
}

// Two bytes of text ("0,") make a value of about a hundred and fifty: with a budget, the text and the tree are
// charged as the tree grows, and the parse stops where it outgrows the budget (a 54 MB scene of inline arrays
// reached 2.8 GB under --max-memory 1G).
TEST(ParseJson, StopsWhereTheTreeOutgrowsTheMemoryBudget) {
    constexpr std::size_t kValues = 100000;
    std::string text = "{\"a\": [0";
    for (std::size_t i = 1; i < kValues; ++i) text += ",0";
    text += "]}";
    MemoryBudget small(std::uint64_t(4) << 20);  // the text fits; the tree does not
    try {
        parse_json(text, "big.json", &small);
        ADD_FAILURE() << "parsed within 4 MB";
    } catch (const InputError& error) {
        EXPECT_EQ(error.location().file, "big.json");
        EXPECT_EQ(error.location().line, 1);
        EXPECT_GT(error.location().column, 8);
        EXPECT_LT(std::size_t(error.location().column), text.size());
        EXPECT_NE(error.problem().find("the parsed document ("), std::string::npos) << error.what();
        EXPECT_NE(error.problem().find("more than the memory limit of 4.19 MB"), std::string::npos) << error.what();
    }
    MemoryBudget roomy(std::uint64_t(1) << 30);
    const JsonValue document = parse_json(text, "big.json", &roomy);
    ASSERT_EQ(document.members.at(0).second.items.size(), kValues);
    EXPECT_GE(roomy.charged_bytes(), text.size() + kValues * sizeof(JsonValue));
    EXPECT_EQ(parse_json(text, "big.json").members.at(0).second.items.size(), kValues);  // no budget: no limit
}

}  // namespace
}  // namespace isotrace
