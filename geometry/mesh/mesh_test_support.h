#pragma once
// Shared by the mesh tests: input files written to a scratch directory, and the geometric checks that tell
// whether a loaded mesh is the shape it should be.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <string_view>

#include "geometry/mesh/triangle_mesh_data.h"
#include "renderer/core/input_error.h"

namespace isotrace::mesh_test {

// A fresh directory under the system temp directory, removed with everything in it when the test ends.
class ScratchDirectory {
public:
    ScratchDirectory() {
        const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
        std::random_device random;
        path_ = std::filesystem::temp_directory_path() /
                ("isotrace_mesh_" + std::string(test->name()) + "_" + std::to_string(random()) + std::to_string(random()));
        std::filesystem::create_directories(path_);
    }
    ~ScratchDirectory() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;

    // Writes `contents` byte for byte to a new file called `name` and returns its path. Each call gets its own
    // subdirectory: rewriting an existing file makes ext4 flush it to disk on close, which slows loops badly.
    std::string write(const std::string& name, std::string_view contents) {
        const std::filesystem::path directory = path_ / std::to_string(files_written_++);
        std::filesystem::create_directory(directory);
        const std::filesystem::path file = directory / name;
        std::ofstream(file, std::ios::binary).write(contents.data(), std::streamsize(contents.size()));
        return file.string();
    }

    // A path in the directory where nothing has been written.
    std::string path_of(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
    int files_written_ = 0;
};

// The message of the InputError that `action` throws; a test failure (and "") if it throws nothing.
inline std::string input_error_message(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "expected an InputError";
    return "";
}

inline Vec3d corner(const TriangleMeshData& mesh, std::uint32_t index) { return Vec3d(mesh.positions.at(index)); }

// Twice the area, pointing out of the front face.
inline Vec3d area_vector(const TriangleMeshData& mesh, const std::array<std::uint32_t, 3>& t) {
    const Vec3d a = corner(mesh, t[0]);
    return cross(corner(mesh, t[1]) - a, corner(mesh, t[2]) - a);
}

inline double total_area(const TriangleMeshData& mesh) {
    double area = 0;
    for (const auto& t : mesh.triangles) area += 0.5 * length(area_vector(mesh, t));
    return area;
}

// Positive for a closed mesh whose front faces point outwards (divergence theorem).
inline double signed_volume(const TriangleMeshData& mesh) {
    double volume = 0;
    for (const auto& t : mesh.triangles) {
        volume += dot(corner(mesh, t[0]), cross(corner(mesh, t[1]), corner(mesh, t[2]))) / 6.0;
    }
    return volume;
}

// Checks that `mesh` is the unit cube [0,1]^3: 12 triangles, exact bounds, area 6, volume 1, faces outwards.
inline void expect_unit_cube(const TriangleMeshData& mesh) {
    EXPECT_EQ(mesh.triangles.size(), 12u);
    const MeshBounds box = mesh.bounds();
    EXPECT_EQ(box.min, Vec3f(0, 0, 0));
    EXPECT_EQ(box.max, Vec3f(1, 1, 1));
    EXPECT_NEAR(total_area(mesh), 6.0, 1e-12);
    EXPECT_NEAR(signed_volume(mesh), 1.0, 1e-12);
    const Vec3d center(0.5, 0.5, 0.5);
    for (const auto& t : mesh.triangles) {
        const Vec3d centroid = (corner(mesh, t[0]) + corner(mesh, t[1]) + corner(mesh, t[2])) / 3.0;
        EXPECT_GT(dot(area_vector(mesh, t), centroid - center), 0.0) << "triangle faces inwards";
    }
}

}  // namespace isotrace::mesh_test
