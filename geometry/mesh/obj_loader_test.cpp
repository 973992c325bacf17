#include "geometry/mesh/obj_loader.h"

#include <gtest/gtest.h>

#include "geometry/mesh/mesh_test_support.h"

namespace isotrace {
namespace {

using mesh_test::expect_unit_cube;
using mesh_test::input_error_message;
using mesh_test::ScratchDirectory;

constexpr const char* cube_positions = R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
)";

// Quads wound counter-clockwise seen from outside, split over two groups.
constexpr const char* cube_faces = R"(o lower
f 1 4 3 2
f 1 2 6 5
f 1 5 8 4
g upper
f 5 6 7 8
f 4 8 7 3
f 2 3 7 6
)";

TEST(ObjLoader, CubeOfQuadsWithoutAttributes) {
    ScratchDirectory scratch;
    const TriangleMeshData mesh = load_obj(scratch.write("cube.obj", std::string(cube_positions) + cube_faces));
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_TRUE(mesh.uvs.empty());
    expect_unit_cube(mesh);
}

TEST(ObjLoader, PerFaceNormalsAndUvsSplitVertices) {
    ScratchDirectory scratch;
    // One normal per cube side and four uv corners; every face corner is a different (v, vt, vn) triple.
    const std::string text = std::string(cube_positions) + R"(vn 0 0 -1
vn 0 -1 0
vn -1 0 0
vn 0 0 1
vn 0 1 0
vn 1 0 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
f 1/1/1 4/2/1 3/3/1 2/4/1
f 1/1/2 2/2/2 6/3/2 5/4/2
f 1/1/3 5/2/3 8/3/3 4/4/3
f 5/1/4 6/2/4 7/3/4 8/4/4
f 4/1/5 8/2/5 7/3/5 3/4/5
f 2/1/6 3/2/6 7/3/6 6/4/6
)";
    const TriangleMeshData mesh = load_obj(scratch.write("cube.obj", text));
    EXPECT_EQ(mesh.positions.size(), 24u);
    ASSERT_EQ(mesh.normals.size(), 24u);
    ASSERT_EQ(mesh.uvs.size(), 24u);
    expect_unit_cube(mesh);
    // Each triangle's shading normals are exactly its side's normal.
    for (const auto& t : mesh.triangles) {
        const Vec3d geometric = normalize(mesh_test::area_vector(mesh, t));
        for (const std::uint32_t v : t) EXPECT_EQ(Vec3d(mesh.normals[v]), geometric);
    }
    // The first face's corners keep their own uvs.
    const auto& first = mesh.triangles[0];
    EXPECT_EQ(mesh.uvs[first[0]], (std::array<float, 2>{0, 0}));
    EXPECT_EQ(mesh.uvs[first[1]], (std::array<float, 2>{1, 0}));
    EXPECT_EQ(mesh.uvs[first[2]], (std::array<float, 2>{1, 1}));
}

TEST(ObjLoader, NormalsSharedWithPositionsNeedNoSplit) {
    ScratchDirectory scratch;
    std::string text = cube_positions;
    for (int i = 0; i < 8; ++i) text += "vn 0 0 1\n";
    text += R"(f 1//1 4//4 3//3 2//2
f 1//1 2//2 6//6 5//5
f 1//1 5//5 8//8 4//4
f 5//5 6//6 7//7 8//8
f 4//4 8//8 7//7 3//3
f 2//2 3//3 7//7 6//6
)";
    const TriangleMeshData mesh = load_obj(scratch.write("cube.obj", text));
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_EQ(mesh.normals.size(), 8u);
    expect_unit_cube(mesh);
}

TEST(ObjLoader, NormalsOnSomeFacesOnlyAreDropped) {
    ScratchDirectory scratch;
    const std::string text = std::string(cube_positions) + "vn 0 0 -1\nf 1//1 4//1 3//1 2//1\n" +
                             "f 1 2 6 5\nf 1 5 8 4\nf 5 6 7 8\nf 4 8 7 3\nf 2 3 7 6\n";
    const TriangleMeshData mesh = load_obj(scratch.write("cube.obj", text));
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_TRUE(mesh.normals.empty());
    expect_unit_cube(mesh);
}

TEST(ObjLoader, PentagonIsFanTriangulated) {
    ScratchDirectory scratch;
    const TriangleMeshData mesh =
        load_obj(scratch.write("pentagon.obj", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n"));
    using Triangle = std::array<std::uint32_t, 3>;
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
}

TEST(ObjLoader, MissingFileNamesIt) {
    ScratchDirectory scratch;
    const std::string path = scratch.path_of("absent.obj");
    const std::string message = input_error_message([&] { load_obj(path); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("file not found"), std::string::npos) << message;
}

TEST(ObjLoader, ParseErrorNamesFileAndLine) {
    ScratchDirectory scratch;
    const std::string path = scratch.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n# comment\nf 0 1 2\n");
    const std::string message = input_error_message([&] { load_obj(path); });
    EXPECT_EQ(message.rfind(path + ":5: ", 0), 0u) << message;
}

TEST(ObjLoader, VertexIndexOutOfRangeNamesFace) {
    ScratchDirectory scratch;
    const std::string path = scratch.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
    EXPECT_EQ(input_error_message([&] { load_obj(path); }),
              path + ": face 2: vertex index 9 out of range (vertex count 3)");
}

TEST(ObjLoader, NormalIndexOutOfRangeNamesFace) {
    ScratchDirectory scratch;
    const std::string path = scratch.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n");
    EXPECT_EQ(input_error_message([&] { load_obj(path); }),
              path + ": face 1: normal index 2 out of range (normal count 1)");
}

TEST(ObjLoader, FileWithoutFacesIsAnError) {
    ScratchDirectory scratch;
    const std::string path = scratch.write("points.obj", cube_positions);
    EXPECT_EQ(input_error_message([&] { load_obj(path); }), path + ": mesh has no triangles");
}

}  // namespace
}  // namespace isotrace
