#include "geometry/mesh/obj_syntax_check.h"

#include <gtest/gtest.h>

#include "geometry/mesh/obj_loader.h"
#include "geometry/mesh/mesh_test_support.h"
#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

using mesh_test::input_error_message;

std::string message_for(const std::string& text) {
    return input_error_message([&] { check_obj_syntax(text, "m.obj"); });
}

TEST(ObjSyntaxCheck, AcceptsOrdinaryFiles) {
    EXPECT_NO_THROW(check_obj_syntax("# cube\nv 0 0 0\nv 1 0 0 1\nv +1 1e-3 -2.5E2\nvt 0.5 0.5\nvn 0 0 1\n"
                                     "f 1 2 3\nf 1/1 2/1 3/1\nf 1//1 2//1 3//1\nf -1/-1/-1 -2/1/1 -3/1/1\n"
                                     "o name with words\ng group\nusemtl red\ns off\nl 1 2\np 1\n\r\n",
                                     "m.obj"));
}

// tinyobjloader read the index 4294967299 as 3 (32-bit wrap-around): a different triangle, silently.
TEST(ObjSyntaxCheck, IndexBeyond32BitsIsRejectedNotWrapped) {
    EXPECT_EQ(message_for("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967299\n"),
              "m.obj:4: f line: \"4294967299\" is not a valid index (whole numbers from 1, or negative, within 32 "
              "bits; v, v/vt, v//vn or v/vt/vn)");
    EXPECT_NE(message_for("f 1//99999999999 2 3\n").find("99999999999"), std::string::npos);
    EXPECT_NE(message_for("f 0 1 2\n").find("\"0\""), std::string::npos);
    EXPECT_NE(message_for("f 1 2 x\n").find("\"x\""), std::string::npos);
    EXPECT_NE(message_for("f 1/2/3/4 2 3\n").find("1/2/3/4"), std::string::npos);
    EXPECT_NE(message_for("f /1 2 3\n").find("/1"), std::string::npos);
}

// tinyobjloader read "nan" and "abc" as 0: a vertex silently moved to the origin.
TEST(ObjSyntaxCheck, NonNumericOrNonFiniteCoordinatesAreRejected) {
    EXPECT_EQ(message_for("v 0 0 0\nv nan 0 0\n"), "m.obj:2: v line: \"nan\" is not a finite number");
    EXPECT_EQ(message_for("v abc 0 0\n"), "m.obj:1: v line: \"abc\" is not a finite number");
    EXPECT_EQ(message_for("vn 0 0 inf\n"), "m.obj:1: vn line: \"inf\" is not a finite number");
    EXPECT_EQ(message_for("v 1e999 0 0\n"), "m.obj:1: v line: \"1e999\" is not a finite number");
    EXPECT_EQ(message_for("v 1 2\n"), "m.obj:1: v line: expected at least 3 values, found 2");
}

TEST(ObjSyntaxCheck, TheLoaderRunsTheCheck) {
    mesh_test::ScratchDirectory scratch;
    const std::string path = scratch.write("wrapped.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 4294967299\n");
    EXPECT_EQ(input_error_message([&] { load_obj(path); }).rfind(path + ":5: f line:", 0), 0u);
}

}  // namespace
}  // namespace isotrace
