#include "geometry/mesh/mesh_file.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "geometry/mesh/mesh_test_support.h"
#include "tests/support/test_time_scale.h"

namespace isotrace {
namespace {

using mesh_test::input_error_message;
using mesh_test::ScratchDirectory;

constexpr const char* triangle_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
constexpr const char* triangle_ply =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

TEST(MeshFile, ChoosesLoaderByExtensionInAnyCase) {
    MemoryBudget memory;
    ScratchDirectory scratch;
    for (const char* name : {"a.obj", "b.OBJ", "c.Obj"}) {
        EXPECT_EQ(load_mesh_file(scratch.write(name, triangle_obj), memory).triangles.size(), 1u) << name;
    }
    for (const char* name : {"a.ply", "b.PLY", "c.pLy"}) {
        EXPECT_EQ(load_mesh_file(scratch.write(name, triangle_ply), memory).triangles.size(), 1u) << name;
    }
}

TEST(MeshFile, WrongContentForExtensionIsReported) {
    MemoryBudget memory;
    ScratchDirectory scratch;
    const std::string path = scratch.write("really_obj.ply", triangle_obj);
    EXPECT_EQ(input_error_message([&] { load_mesh_file(path, memory); }),
              path + ":1: not a PLY file (the first line must be 'ply')");
}

TEST(MeshFile, UnsupportedExtensionListsSupportedOnes) {
    MemoryBudget memory;
    ScratchDirectory scratch;
    const std::string stl = scratch.write("cube.stl", "solid cube\n");
    EXPECT_EQ(input_error_message([&] { load_mesh_file(stl, memory); }),
              stl + ": unsupported file extension '.stl' (supported mesh formats: .obj, .ply, .bpt)");
    const std::string bare = scratch.write("cube", triangle_obj);
    EXPECT_EQ(input_error_message([&] { load_mesh_file(bare, memory); }),
              bare + ": no file extension (supported mesh formats: .obj, .ply, .bpt)");
}

TEST(MeshFile, DirectoryIsNotAMesh) {
    MemoryBudget memory;
    ScratchDirectory scratch;
    const std::string path = scratch.path_of("folder.obj");
    std::filesystem::create_directory(path);
    EXPECT_EQ(input_error_message([&] { load_mesh_file(path, memory); }),
              path + ": is a directory, not a regular file (isotrace reads only regular files)");
}

TEST(MeshFile, LoadsTheStanfordBunny) {
    MemoryBudget memory;
    const auto start = std::chrono::steady_clock::now();
    const TriangleMeshData bunny = load_mesh_file(ISOTRACE_SCENES_DIR "/data/bunny.obj", memory);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(bunny.triangles.size(), 27864u);
    // The file pairs every position with the normal of the same number, so no vertex is split.
    EXPECT_EQ(bunny.positions.size(), 13934u);
    EXPECT_EQ(bunny.normals.size(), 13934u);
    EXPECT_TRUE(bunny.uvs.empty());
    const MeshBounds box = bunny.bounds();
    EXPECT_TRUE(is_finite(box.min) && is_finite(box.max));
    EXPECT_LT(box.min.x, box.max.x);
    EXPECT_LT(box.min.y, box.max.y);
    EXPECT_LT(box.min.z, box.max.z);
    EXPECT_LT(seconds, 2.0 * testing::kTestTimeScale) << "loading a 1.9 MB OBJ should be fast";
}

}  // namespace
}  // namespace isotrace
