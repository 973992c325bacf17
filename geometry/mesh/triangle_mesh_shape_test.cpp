// Triangle meshes through a real RenderScene: a unit cube given inline and as a file, hit distances, the
// counter-clockwise front as the geometric normal (outward for the cube, also after a mirroring transform),
// interpolated shading normals and uvs, baked transforms, and the inline format's errors.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "geometry/mesh/mesh_test_support.h"
#include "geometry/mesh/triangle_mesh_shape.h"
#include "renderer/embree/triangle_hit.h"
#include "renderer/scene/loaded_scene.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {
namespace {

using mesh_test::input_error_message;
using mesh_test::ScratchDirectory;

// Vertex i = (i & 1, (i >> 1) & 1, (i >> 2) & 1); triangles counter-clockwise seen from outside.
constexpr const char* kCubePositions =
    "[[0,0,0],[1,0,0],[0,1,0],[1,1,0],[0,0,1],[1,0,1],[0,1,1],[1,1,1]]";
constexpr const char* kCubeTriangles =
    "[[0,2,3],[0,3,1],[4,5,7],[4,7,6],[0,1,5],[0,5,4],[2,6,7],[2,7,3],[0,4,6],[0,6,2],[1,3,7],[1,7,5]]";

TriangleMeshData unit_cube() {
    TriangleMeshData mesh;
    for (std::uint32_t i = 0; i < 8; ++i) mesh.positions.push_back(Vec3f(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)));
    mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                      {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return mesh;
}

std::string scene_json(const std::string& shape, const std::string& transform = "") {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"material": "m", )" +
           (transform.empty() ? "" : "\"transform\": " + transform + ", ") + "\"shape\": " + shape + "}]}";
}

std::unique_ptr<RenderScene> mesh_scene(TriangleMeshData mesh, const Transform& to_world = {}) {
    auto scene = std::make_unique<RenderScene>();
    SceneObject object;
    object.shape = std::make_unique<TriangleMeshShape>(std::move(mesh));
    object.to_world = to_world;
    scene->add_object(std::move(object));
    scene->commit();
    return scene;
}

Ray make_ray(const Vec3f& o, const Vec3f& d, float t_near = 0, float t_far = INFINITY) {
    Ray ray;
    ray.origin = o;
    ray.direction = d;
    ray.t_near = t_near;
    ray.t_far = t_far;
    return ray;
}

void expect_vec_near(const Vec3f& actual, const Vec3d& expected, double tolerance, const std::string& what = "") {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

// Shoots rays at every face of the box T([0,1]^3) from outside and from inside, checking the distance and
// that the geometric normal is the outward face normal (inverse transpose of the object-space axis).
void check_box(const RenderScene& scene, const Transform& to_world, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> inner(0.05, 0.95);
    const Transform to_object = to_world.inverse();
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            Vec3d outward(0, 0, 0);
            outward[axis] = side ? 1 : -1;
            const Vec3d world_normal = normalize(to_world.normal(outward));
            for (int i = 0; i < 20; ++i) {
                Vec3d on_face{inner(random), inner(random), inner(random)};
                on_face[axis] = side;
                Vec3d start = on_face + outward * 1.5 + Vec3d{inner(random) - 0.5, inner(random) - 0.5, inner(random) - 0.5} * 0.2;
                start[axis] = side ? 2.0 : -1.0;
                // From outside towards the face point.
                const Vec3f o(to_world.point(start));
                const Vec3f d(to_world.point(on_face) - to_world.point(start));
                const Vec3d oo = to_object.point(Vec3d(o)), od = to_object.vector(Vec3d(d));
                const double t = (on_face[axis] - oo[axis]) / od[axis];
                const auto hit = scene.intersect(make_ray(o, d), RayKind::Camera);
                ASSERT_TRUE(hit) << "axis " << axis << " side " << side << " ray " << i;
                EXPECT_NEAR(hit->t, t, 1e-5 * t);
                expect_vec_near(hit->geometric_normal, world_normal, 1e-5,
                                "outside, axis " + std::to_string(axis) + " side " + std::to_string(side));
                EXPECT_LT(dot(hit->geometric_normal, d), 0.0f);
                EXPECT_TRUE(scene.occluded(make_ray(o, d)));
                EXPECT_FALSE(scene.occluded(make_ray(o, d, 0, float(t) * 0.999f)));
                // From the centre outwards through the same point: the normal is still the outward one.
                const Vec3f ci(to_world.point(Vec3d(0.5, 0.5, 0.5)));
                const Vec3f di(to_world.point(on_face) - to_world.point(Vec3d(0.5, 0.5, 0.5)));
                const auto exit = scene.intersect(make_ray(ci, di), RayKind::Camera);
                ASSERT_TRUE(exit);
                EXPECT_NEAR(exit->t, 1.0, 1e-5);
                expect_vec_near(exit->geometric_normal, world_normal, 1e-5, "exit normal");
                EXPECT_GT(dot(exit->geometric_normal, di), 0.0f);
            }
        }
    }
}

TEST(TriangleMeshShape, InlineCubeHitsAndOutwardGeometricNormals) {
    ScratchDirectory dir;
    const std::string path = dir.write(
        "cube.json", scene_json(std::string(R"({"type": "mesh", "positions": )") + kCubePositions +
                                ", \"triangles\": " + kCubeTriangles + "}"));
    const auto loaded = load_scene(path);
    ASSERT_EQ(loaded->scene->objects().size(), 1u);
    EXPECT_EQ(loaded->scene->objects()[0].shape->primitive_count(), 12u);
    EXPECT_FALSE(loaded->scene->objects()[0].instanced);
    check_box(*loaded->scene, Transform(), 1);
    // Without shading normals the shading normal is the geometric one, and uv the barycentrics.
    const auto hit = loaded->scene->intersect(make_ray({0.25f, 0.5f, -1}, {0, 0, 1}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->shading_normal, hit->geometric_normal);
    EXPECT_EQ(hit->geometric_normal, Vec3f(0, 0, -1));
    EXPECT_FLOAT_EQ(hit->t, 1.0f);
    EXPECT_TRUE(hit->primitive_id == 0 || hit->primitive_id == 1);
}

// Embree's t, u and v are products with an approximate reciprocal whose last bits differ between CPU makers; a hit
// reports its triangle's solution in plain float arithmetic instead, so that renders of meshes are the same on every
// machine. Rays from all around at a turned and stretched cube: most of Embree's own distances differ from that.
TEST(TriangleMeshShape, HitsAreSolvedAgainRatherThanTakenFromEmbree) {
    const Transform to_world = Transform::translate({0.3, -0.2, 0.1}) *
                               Transform::rotate(Vec3d(1, 2, 3), 40) * Transform::scale({1.3, 0.8, 1.1});
    const auto scene = mesh_scene(unit_cube(), to_world);
    const TriangleView mesh = scene->objects()[0].shape->embree_triangles();
    ASSERT_EQ(mesh.triangles.size(), 12u);
    std::mt19937 random(11);
    std::uniform_real_distribution<float> around(-3, 3), inside(0.1f, 0.9f);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3f origin(around(random), around(random), around(random));
        const Vec3f target(to_world.point(Vec3d(inside(random), inside(random), inside(random))));
        const Vec3f direction = target - origin;
        const auto hit = scene->intersect(make_ray(origin, direction), RayKind::Camera);
        ASSERT_TRUE(hit) << i;
        ++hits;
        RTCHit solved{};
        solved.primID = hit->primitive_id;
        float t = -1;
        resolve_triangle_hit(mesh, origin, direction, solved, t);
        EXPECT_EQ(hit->t, t) << i;
        EXPECT_EQ(hit->uv[0], solved.u) << i;
        EXPECT_EQ(hit->uv[1], solved.v) << i;
    }
    EXPECT_EQ(hits, 2000);
}

TEST(TriangleMeshShape, CubeFromObjFileMatchesInline) {
    ScratchDirectory dir;
    const std::string obj = dir.write("cube.obj",
                                      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                      "f 1 4 3 2\nf 1 2 6 5\nf 1 5 8 4\nf 5 6 7 8\nf 4 8 7 3\nf 2 3 7 6\n");
    const std::string path = dir.write("scene.json", scene_json(R"({"type": "mesh", "file": ")" + obj + "\"}"));
    const auto loaded = load_scene(path);
    EXPECT_EQ(loaded->scene->objects()[0].shape->primitive_count(), 12u);
    check_box(*loaded->scene, Transform(), 2);
}

TEST(TriangleMeshShape, CubeFromPlyFileWithRelativePath) {
    ScratchDirectory dir;
    const std::string ply = dir.write("cube.ply",
                                      "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
                                      "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n"
                                      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                                      "4 0 3 2 1\n4 0 1 5 4\n4 0 4 7 3\n4 4 5 6 7\n4 3 7 6 2\n4 1 2 6 5\n");
    // The scene sits in a sibling directory: "file" resolves against the scene's own directory.
    const std::filesystem::path relative =
        std::filesystem::path("..") / std::filesystem::path(ply).parent_path().filename() / "cube.ply";
    const std::string path = dir.write("scene.json", scene_json(R"({"type": "mesh", "file": ")" + relative.string() + "\"}"));
    const auto loaded = load_scene(path);
    check_box(*loaded->scene, Transform(), 3);
}

TEST(TriangleMeshShape, ShadingNormalsAreInterpolatedAndNormalised) {
    TriangleMeshData mesh;
    mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};  // front (counter-clockwise) faces +z
    mesh.normals = {{0, 0, 1}, {3, 0, 3}, {0, -1, 2}};   // any length
    mesh.triangles = {{0, 1, 2}};
    const auto scene = mesh_scene(mesh);
    for (const auto& [x, y] : {std::pair{0.2f, 0.3f}, std::pair{1.0f, 0.5f}, std::pair{0.1f, 1.7f}, std::pair{0.5f, 0.5f}}) {
        const auto hit = scene->intersect(make_ray({x, y, 3}, {0, 0, -1}), RayKind::Camera);
        ASSERT_TRUE(hit);
        EXPECT_FLOAT_EQ(hit->t, 3.0f);
        EXPECT_EQ(hit->geometric_normal, Vec3f(0, 0, 1));
        const double u = x / 2.0, v = y / 2.0, w = 1 - u - v;  // weights of vertices 1 and 2, and 0
        const Vec3d n = Vec3d(mesh.normals[0]) * w + Vec3d(mesh.normals[1]) * u + Vec3d(mesh.normals[2]) * v;
        expect_vec_near(hit->shading_normal, normalize(n), 1e-5, "shading normal at " + std::to_string(x));
        EXPECT_NEAR(length(hit->shading_normal), 1.0, 1e-6);
        // uv without a uv table: the barycentrics of vertices 1 and 2.
        EXPECT_NEAR(hit->uv[0], u, 1e-6);
        EXPECT_NEAR(hit->uv[1], v, 1e-6);
    }
    // Seen from behind: the geometric normal keeps the front orientation.
    const auto back = scene->intersect(make_ray({0.2f, 0.3f, -3}, {0, 0, 1}), RayKind::Camera);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->geometric_normal, Vec3f(0, 0, 1));
}

TEST(TriangleMeshShape, ShadingNormalIsTurnedToTheGeometricSide) {
    TriangleMeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals = {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}};  // authored against the winding
    mesh.triangles = {{0, 1, 2}};
    const auto scene = mesh_scene(mesh);
    const auto hit = scene->intersect(make_ray({0.25f, 0.25f, 1}, {0, 0, -1}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->geometric_normal, Vec3f(0, 0, 1));
    EXPECT_EQ(hit->shading_normal, Vec3f(0, 0, 1));
}

TEST(TriangleMeshShape, UvsAreInterpolated) {
    ScratchDirectory dir;
    const std::string path = dir.write("uv.json", scene_json(R"({"type": "mesh",
        "positions": [[0, 0, 0], [4, 0, 0], [0, 4, 0], [4, 4, 0]],
        "uvs": [[0.1, 0.2], [0.9, 0.2], [0.1, 0.6], [0.9, 0.6]],
        "triangles": [[0, 1, 3], [0, 3, 2]]})"));
    const auto loaded = load_scene(path);
    std::mt19937 random(9);
    std::uniform_real_distribution<float> coordinate(0.01f, 3.99f);
    for (int i = 0; i < 100; ++i) {
        const float x = coordinate(random), y = coordinate(random);
        const auto hit = loaded->scene->intersect(make_ray({x, y, 2}, {0, 0, -1}), RayKind::Camera);
        ASSERT_TRUE(hit);
        // The uvs are an affine function of position, so interpolation reproduces it on both triangles.
        EXPECT_NEAR(hit->uv[0], 0.1 + 0.8 * x / 4, 1e-5) << x << ", " << y;
        EXPECT_NEAR(hit->uv[1], 0.2 + 0.4 * y / 4, 1e-5) << x << ", " << y;
        EXPECT_EQ(hit->primitive_id, x > y ? 0u : 1u);
    }
}

// The shading of a hit on triangle `primitive` at barycentrics (u, v), as the scene would ask for it.
LocalShading shading_at(const TriangleMeshShape& shape, unsigned primitive, float u = 0.25f, float v = 0.25f) {
    RTCHit hit{};
    hit.primID = primitive;
    hit.u = u;
    hit.v = v;
    return shape.shading(hit, {0, 0, 1}, {});
}

TEST(TriangleMeshShape, UvDerivativesAreThoseOfTheTrianglesAffineMap) {
    // p(u, v) = (u − 0.1)·A + (v − 0.2)·B at the corners' uvs.
    const Vec3d a(4, 0, 0), b(0, 3, 1);
    const std::array<std::array<float, 2>, 3> uvs{{{0.1f, 0.2f}, {0.6f, 0.2f}, {0.3f, 0.9f}}};
    TriangleMeshData mesh;
    for (const auto& uv : uvs) {
        mesh.positions.push_back(Vec3f(a * (double(uv[0]) - 0.1) + b * (double(uv[1]) - 0.2)));
        mesh.uvs.push_back(uv);
    }
    mesh.triangles = {{0, 1, 2}};
    TriangleMeshShape shape(mesh);
    EXPECT_TRUE(shape.has_uv());
    EXPECT_EQ(shape.hit_shading(), HitShading::Computed);
    LocalShading shading = shading_at(shape, 0);
    expect_vec_near(shading.dpdu, a, 1e-5);
    expect_vec_near(shading.dpdv, b, 1e-5);
    // Baked by a mirror the corners are reordered, and the derivatives follow the moved positions.
    shape.bake(Transform::scale({-1, 2, 1}));
    shading = shading_at(shape, 0);
    expect_vec_near(shading.dpdu, {-4, 0, 0}, 1e-5);
    expect_vec_near(shading.dpdv, {0, 6, 1}, 1e-5);
}

TEST(TriangleMeshShape, CollinearUvsGiveZeroDerivativesAndMeshesWithoutUvsKeepEmbreesShading) {
    TriangleMeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh.uvs = {{0, 0}, {0.5f, 0.5f}, {1, 1}, {1, 0}};  // the first triangle's uvs lie on a line
    mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    const TriangleMeshShape shape(mesh);
    EXPECT_EQ(shading_at(shape, 0).dpdu, Vec3f(0, 0, 0));
    EXPECT_EQ(shading_at(shape, 0).dpdv, Vec3f(0, 0, 0));
    EXPECT_NE(shading_at(shape, 1).dpdu, Vec3f(0, 0, 0));
    mesh.uvs.clear();
    const TriangleMeshShape plain(mesh);
    EXPECT_FALSE(plain.has_uv());
    EXPECT_EQ(plain.hit_shading(), HitShading::EmbreeHit);
}

TEST(TriangleMeshShape, AffineTransformIsBakedWithOutwardNormals) {
    const Transform to_world =
        Transform::translate({1, 2, -3}) * Transform::rotate({1, 2, 3}, 50) * Transform::scale({2, 0.5, 3});
    const auto scene = mesh_scene(unit_cube(), to_world);
    EXPECT_FALSE(scene->objects()[0].instanced);
    EXPECT_EQ(scene->build_statistics().instanced_objects, 0u);
    check_box(*scene, to_world, 4);
}

TEST(TriangleMeshShape, MirroringTransformKeepsNormalsOutward) {
    for (const Transform& mirror :
         {Transform::scale({-1, 1, 1}), Transform::translate({0.5, 0, 1}) * Transform::scale({1, -2, 1}),
          Transform::rotate({0, 1, 1}, 20) * Transform::scale({-1, -1, -1.5})}) {
        ASSERT_LT(mirror.determinant(), 0);
        const auto scene = mesh_scene(unit_cube(), mirror);
        check_box(*scene, mirror, 5);
    }
}

TEST(TriangleMeshShape, MirroredShadingNormalsAndUvsFollowTheirVertices) {
    TriangleMeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
    mesh.triangles = {{0, 1, 2}};
    const Transform mirror = Transform::scale({-1, 1, 1});  // x -> -x
    const auto scene = mesh_scene(mesh, mirror);
    const float x = 0.25f, y = 0.5f;  // object point; world point (-x, y)
    const auto hit = scene->intersect(make_ray({-x, y, 2}, {0, 0, -1}), RayKind::Camera);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->geometric_normal, Vec3f(0, 0, 1));  // the front still faces +z
    const Vec3d object_normal = Vec3d(0, 0, 1) * double(1 - x - y) + Vec3d(1, 0, 1) * double(x) + Vec3d(0, 1, 1) * double(y);
    expect_vec_near(hit->shading_normal, normalize(Vec3d(-object_normal.x, object_normal.y, object_normal.z)), 1e-5);
    EXPECT_NEAR(hit->uv[0], x, 1e-6);
    EXPECT_NEAR(hit->uv[1], y, 1e-6);
    // Without a uv table the fallback uv stays the barycentrics of the authored second and third corners.
    mesh.uvs.clear();
    const auto plain = mesh_scene(mesh, mirror);
    const auto plain_hit = plain->intersect(make_ray({-x, y, 2}, {0, 0, -1}), RayKind::Camera);
    ASSERT_TRUE(plain_hit);
    EXPECT_NEAR(plain_hit->uv[0], x, 1e-6);
    EXPECT_NEAR(plain_hit->uv[1], y, 1e-6);
}

TEST(TriangleMeshShape, InlineTransformFromSceneFileIsBaked) {
    ScratchDirectory dir;
    const std::string path = dir.write(
        "t.json", scene_json(std::string(R"({"type": "mesh", "positions": )") + kCubePositions +
                                 ", \"triangles\": " + kCubeTriangles + "}",
                             R"({"scale": [-2, 1, 1], "translate": [0, 0, 1]})"));
    const auto loaded = load_scene(path);
    const Transform& to_world = loaded->scene->objects()[0].to_world;
    EXPECT_LT(to_world.determinant(), 0);
    check_box(*loaded->scene, to_world, 6);
}

// ---- inline format errors ---------------------------------------------------------------------------------

TEST(TriangleMeshShapeScene, IndexOutOfRangeNamesTheTriangleAndItsPosition) {
    ScratchDirectory dir;
    const std::string path = dir.write("bad.json", scene_json(R"({"type": "mesh",
        "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
        "triangles": [[0, 1, 2],
                      [0, 1, 3]]})"));
    const std::string message = input_error_message([&] { load_scene(path); });
    EXPECT_NE(message.find(path + ":7:23"), std::string::npos) << message;
    EXPECT_NE(message.find("objects[0].shape.triangles[1]"), std::string::npos) << message;
    EXPECT_NE(message.find("vertex index 3 is not an index into positions (3 vertices)"), std::string::npos) << message;
}

TEST(TriangleMeshShapeScene, NegativeAndFractionalIndicesAreRejected) {
    ScratchDirectory dir;
    for (const char* triangle : {"[0, -1, 2]", "[0, 1.5, 2]"}) {
        const std::string path = dir.write(
            "bad.json",
            scene_json(std::string(R"({"type": "mesh", "positions": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [)") +
                       triangle + "]}"));
        const std::string message = input_error_message([&] { load_scene(path); });
        EXPECT_NE(message.find("triangles[0]"), std::string::npos) << message;
        EXPECT_NE(message.find("not an index"), std::string::npos) << message;
        EXPECT_EQ(message.find(".000000"), std::string::npos) << message;
    }
}

TEST(TriangleMeshShapeScene, MissingPartsAreInputErrors) {
    ScratchDirectory dir;
    struct Case {
        const char* shape;
        const char* expected;
    };
    const Case cases[] = {
        {R"({"type": "mesh", "positions": [[0,0,0],[1,0,0],[0,1,0]]})", "triangles"},
        {R"({"type": "mesh", "triangles": [[0, 1, 2]]})", "positions"},
        {R"({"type": "mesh"})", "positions"},
        {R"({"type": "mesh", "positions": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0, 1, 1]]})", "no triangles"},
        {R"({"type": "mesh", "positions": [[0,0,0],[1,0,0],[0,1,0]], "normals": [[0,0,1]], "triangles": [[0,1,2]]})",
         "normals"},
        {R"({"type": "mesh", "positions": [[0,0,0],[1,0,0],[0,1,0]], "uvs": [[0,0],[1,0],[0]], "triangles": [[0,1,2]]})",
         "[u, v]"},
        {R"({"type": "mesh", "file": "cube.obj", "positions": [[0,0,0]]})", "not both"},
        {R"({"type": "mesh", "file": "missing.obj"})", "file not found"},
    };
    for (const Case& c : cases) {
        const std::string path = dir.write("bad.json", scene_json(c.shape));
        const std::string message = input_error_message([&] { load_scene(path); });
        EXPECT_NE(message.find(c.expected), std::string::npos) << c.shape << "\n" << message;
        EXPECT_NE(message.find("objects[0].shape"), std::string::npos) << c.shape << "\n" << message;
    }
}

// A mesh file's own error used to name only the mesh file, not where the scene refers to it.
TEST(TriangleMeshShapeScene, ErrorInsideTheMeshFileNamesTheSceneLineThatReferencesIt) {
    ScratchDirectory dir;
    const std::string obj = dir.write("broken.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
    const std::string path = dir.write("scene.json", scene_json(R"({"type": "mesh", "file": ")" + obj + "\"}"));
    const std::string message = input_error_message([&] { load_scene(path); });
    EXPECT_EQ(message.rfind(path + ":", 0), 0u) << message;  // the scene file first
    EXPECT_NE(message.find("objects[0].shape.file: " + obj + ":3: v line: \"nan\""), std::string::npos) << message;
}

}  // namespace
}  // namespace isotrace
