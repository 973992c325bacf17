// The deformer plugins end to end (JSON → measured radii → binding → edits → mesh), and radius measurement.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/mesh/mesh_deformer.h"
#include "geometry/mesh/mesh_test_support.h"
#include "geometry/sweep/radius_measurement.h"
#include "geometry/sweep/sweep_surface.h"
#include "geometry/sweep/sweep_tessellation.h"
#include "geometry/sweep/sweep_test_support.h"

namespace isotrace {
namespace {

using mesh_test::input_error_message;
using mesh_test::ScratchDirectory;

// A closed tube of radius 0.5 from z = 0 to z = 2, finely tessellated.
TriangleMeshData cylinder_mesh() { return tessellate(SweepSurface(sweep_test::cylinder(0.5, 2, 4)), {256, 16, true}); }

TEST(RadiusProbe, MeasuresTheDistanceToTheNearestSurfaceInTheSectionPlane) {
    const RadiusProbe probe(cylinder_mesh());
    // An inscribed 256-gon: between 0.5·cos(π/256) and 0.5.
    for (double r : probe.measure({0, 0, 1}, Quaternion::identity(), 16)) {
        EXPECT_LE(r, 0.5 + 1e-6);
        EXPECT_GE(r, 0.5 * std::cos(M_PI / 256) - 1e-6);
    }
    // Off-centre by 0.2 along x: the ray along +x meets the wall after 0.3, the one along −x after 0.7.
    const std::vector<double> off = probe.measure({0.2, 0, 1}, Quaternion::identity(), 4);
    EXPECT_NEAR(off[0], 0.3, 1e-4);
    EXPECT_NEAR(off[2], 0.7, 1e-4);
    EXPECT_THROW(probe.measure({0, 0, 5}, Quaternion::from_axis_angle({1, 0, 0}, 90), 8), std::invalid_argument);
    EXPECT_THROW(probe.measure({NAN, 0, 1}, Quaternion::identity(), 8), std::invalid_argument);
    EXPECT_THROW(probe.measure({1e300, 0, 1}, Quaternion::identity(), 8), std::invalid_argument);  // inf in float
}

TEST(SweepDeformerPlugins, UneditedSweepWithMeasuredRadiiLeavesTheMeshInPlace) {
    ScratchDirectory scratch;
    const std::string path = scratch.write("identity.json", R"({"deformers": [
      {"type": "sweep", "mode": "global", "measured_radius_scale": 1.2,
       "key_sections": [{"center": [0, 0, -0.1], "radius": 0.6}, {"center": [0, 0, 0.7]}, {"center": [0, 0, 1.3]},
                        {"center": [0, 0, 2.1], "radius": 0.6}]}]})");
    TriangleMeshData mesh = cylinder_mesh();
    const std::vector<Vec3f> before = mesh.positions;
    const std::vector<std::string> summaries = apply_mesh_deformer_file(path, mesh, std::make_shared<MemoryBudget>());
    ASSERT_EQ(summaries.size(), 1u);
    EXPECT_NE(summaries[0].find("0 unbound"), std::string::npos) << summaries[0];
    for (std::size_t i = 0; i < before.size(); ++i) EXPECT_LT(length(Vec3d(mesh.positions[i]) - Vec3d(before[i])), 1e-6);
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());  // recomputed
}

TEST(SweepDeformerPlugins, RigidEditOfEveryKeyMovesTheMeshRigidly) {
    // Translating key 0 carries all later key sections along (relative key sections): the whole tube moves.
    ScratchDirectory scratch;
    const std::string path = scratch.write("shift.json", R"({"deformers": [
      {"type": "sweep", "mode": "global",
       "key_sections": [{"center": [0, 0, -0.1], "radius": 0.7}, {"center": [0, 0, 1], "radius": 0.7},
                        {"center": [0, 0, 2.1], "radius": 0.7}],
       "edits": [{"key": 0, "translate": [0.25, -0.5, 0]}]}]})");
    TriangleMeshData mesh = cylinder_mesh();
    const std::vector<Vec3f> before = mesh.positions;
    apply_mesh_deformer_file(path, mesh, std::make_shared<MemoryBudget>());
    for (std::size_t i = 0; i < before.size(); ++i)
        EXPECT_LT(length(Vec3d(mesh.positions[i]) - Vec3d(before[i]) - Vec3d(0.25, -0.5, 0)), 1e-6);
}

TEST(SweepDeformerPlugins, MistakesNameTheirPlace) {
    ScratchDirectory scratch;
    TriangleMeshData mesh = cylinder_mesh();
    const std::string typo = scratch.write("typo.json", R"({"deformers": [{"type": "sweep", "key_sectons": []}]})");
    const auto memory = std::make_shared<MemoryBudget>();
    EXPECT_NE(input_error_message([&] { apply_mesh_deformer_file(typo, mesh, memory); }).find("typo.json:1:16: deformers[0]"),
              std::string::npos);
    const std::string outside = scratch.write("outside.json", R"({"deformers": [{"type": "sweep",
      "key_sections": [{"center": [5, 5, 1]}, {"center": [5, 5, 2]}]}]})");
    EXPECT_EQ(input_error_message([&] { apply_mesh_deformer_file(outside, mesh, memory); }),
              outside + ":2:24: deformers[0].key_sections[0]: radii: the ray at θ = 0° from the centre meets no surface");
    const std::string level = scratch.write("level.json", R"({"deformers": [{"type": "sweep", "levels": 2,
      "key_sections": [{"center": [0, 0, 0], "radius": 0.6}, {"center": [0, 0, 2], "radius": 0.6}],
      "edits": [{"level": 3, "key": 0}]}]})");
    EXPECT_EQ(input_error_message([&] { apply_mesh_deformer_file(level, mesh, memory); }),
              level + ":3:17: deformers[0].edits[0]: level: must be in [1, 2], got 3");
}

// 16 key sections refined over 6 levels: 481 at the finest, 30,721 samples of t for each of the cylinder's
// vertices.
std::string fine_sweep() {
    std::string keys;
    for (int k = 0; k < 16; ++k)
        keys += std::string(k ? ", " : "") + "{\"center\": [0, 0, " + std::to_string(-0.1 + 0.14 * k) + "], \"radius\": 0.7}";
    return R"({"type": "sweep", "mode": "global", "levels": 6, "key_sections": [)" + keys + "]}";
}

// A list of 50 deformers took 19 s, a file of them hours: the list's total work is refused before any of it.
TEST(SweepDeformerPlugins, AListBeyondTheWorkLimitIsRefusedBeforeAnyWork) {
    ScratchDirectory scratch;
    std::string list;
    for (int i = 0; i < 200; ++i) list += (i ? ", " : "") + fine_sweep();
    const std::string path = scratch.write("many.json", R"({"deformers": [)" + list + "]}");
    TriangleMeshData mesh = cylinder_mesh();
    const std::vector<Vec3f> before = mesh.positions;
    const std::string message =
        input_error_message([&] { apply_mesh_deformer_file(path, mesh, std::make_shared<MemoryBudget>()); });
    EXPECT_NE(message.find(path + ":1:15: deformers: 200 deformers on 4354 vertices need about 6.82e+10 steps, more "
                                  "than the limit of 2e+10"),
              std::string::npos)
        << message;
    EXPECT_EQ(mesh.positions, before);
}

// A pull on a parent of many key sections solves ever larger systems, up to max_iterations times.
TEST(SweepDeformerPlugins, APullBeyondTheWorkLimitIsRefusedBeforeAnyWork) {
    ScratchDirectory scratch;
    std::string keys;
    for (int k = 0; k < 200; ++k)
        keys += std::string(k ? ", " : "") + "{\"center\": [0, 0, " + std::to_string(-0.1 + 0.011 * k) + "], \"radius\": 0.7}";
    const std::string path = scratch.write("pull.json", R"({"deformers": [{"type": "sweep_hierarchy", "max_iterations": 10000,
      "sweeps": [{"name": "body", "key_sections": [)" + keys + R"(]},
                 {"name": "handle", "parent": "body", "attachment": "loop",
                  "key_sections": [{"center": [0.3, 0, 0.5], "radius": 0.1}, {"center": [0.3, 0, 1.5], "radius": 0.1}]}],
      "edits": [{"sweep": "handle", "key": 1, "pull": [0, 0, 0.1]}]}]})");
    TriangleMeshData mesh = cylinder_mesh();
    const std::string message =
        input_error_message([&] { apply_mesh_deformer_file(path, mesh, std::make_shared<MemoryBudget>()); });
    EXPECT_NE(message.find("deformers: 1 deformer on 4354 vertices need about"), std::string::npos) << message;
}

// What a deformer holds while it works is charged before it starts: here the traced copy of the mesh that its
// radii are measured on, and its bindings.
TEST(SweepDeformerPlugins, ItsMemoryIsChargedBeforeItWorks) {
    ScratchDirectory scratch;
    const std::string path = scratch.write("measured.json", R"({"deformers": [{"type": "sweep", "mode": "global",
      "key_sections": [{"center": [0, 0, -0.1], "radius": 0.6}, {"center": [0, 0, 1]},
                       {"center": [0, 0, 2.1], "radius": 0.6}]}]})");
    TriangleMeshData mesh = cylinder_mesh();
    const std::string message =
        input_error_message([&] { apply_mesh_deformer_file(path, mesh, std::make_shared<MemoryBudget>(1 << 20)); });
    EXPECT_NE(message.find("deformers: deforming 4354 vertices needs about 2.79 MB"), std::string::npos) << message;
}

}  // namespace
}  // namespace isotrace
