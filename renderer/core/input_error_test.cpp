#include "renderer/core/input_error.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace isotrace {
namespace {

TEST(InputError, NamesFileLineColumnFieldAndProblem) {
    const InputError error({"scenes/box.json", 12, 7}, "objects[1].shape.radius", "must be > 0");
    EXPECT_STREQ(error.what(), "scenes/box.json:12:7: objects[1].shape.radius: must be > 0");
}

TEST(InputError, NulAndControlBytesAreSpelledOutSoTheMessageIsNotCutShort) {
    const InputError error({"a.json", 1, 2}, std::string("objects.ke\0y", 12), std::string("unknown key \"ke\0y\"\x1b!", 20));
    EXPECT_STREQ(error.what(), "a.json:1:2: objects.ke\\x00y: unknown key \"ke\\x00y\"\\x1b!");
    EXPECT_EQ(error.problem(), std::string("unknown key \"ke\0y\"\x1b!", 20));  // raw, for re-throwing
}

TEST(InputError, KeepsLocationAndFieldForCallers) {
    const InputError error({"a.json", 3, 4}, "film.spp", "bad");
    EXPECT_EQ(error.location().file, "a.json");
    EXPECT_EQ(error.location().line, 3);
    EXPECT_EQ(error.location().column, 4);
    EXPECT_EQ(error.field(), "film.spp");
}

TEST(InputError, OmitsUnknownColumn) {
    EXPECT_STREQ(InputError({"a.json", 5, 0}, "camera", "problem").what(), "a.json:5: camera: problem");
}

TEST(InputError, OmitsUnknownLineAndColumn) {
    EXPECT_STREQ(InputError({"mesh.ply", 0, 0}, "", "truncated file").what(), "mesh.ply: truncated file");
}

TEST(InputError, OmitsEmptyField) {
    EXPECT_STREQ(InputError({"a.json", 1, 2}, "", "unexpected text").what(), "a.json:1:2: unexpected text");
}

TEST(InputError, OmitsEmptyFile) {
    // Command-line values have no file; the position is meaningless without one.
    EXPECT_STREQ(InputError({"", 3, 4}, "--spp", "expected a positive integer").what(),
                 "--spp: expected a positive integer");
    EXPECT_STREQ(InputError({}, "", "just the problem").what(), "just the problem");
}

TEST(InputError, IsARuntimeError) {
    try {
        throw InputError({"f", 1, 1}, "x", "y");
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "f:1:1: x: y");
        return;
    }
    FAIL() << "InputError was not caught as std::runtime_error";
}

}  // namespace
}  // namespace isotrace
