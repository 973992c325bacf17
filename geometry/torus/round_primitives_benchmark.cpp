// ns per ray of the round primitives (and of a sphere, for scale): the double-precision solvers alone (frustum_crossings, torus_crossings) and
// whole nearest-hit queries through Embree (RenderScene::intersect, one shape in the scene), on random rays aimed at
// the shape's bounding box from a few sizes away (about half of them hit). Run: build/bin/round_primitives_benchmark
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <vector>

#include "geometry/cone/frustum_shape.h"
#include "geometry/sphere/sphere_intersection.h"
#include "geometry/sphere/sphere_shape.h"
#include "geometry/torus/torus_shape.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {
namespace {

struct Line {
    Vec3d origin, direction;
};

std::vector<Line> random_lines(const Bounds3f& bounds) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(0, 1);
    const Vec3d lower(bounds.lower), size = Vec3d(bounds.upper) - lower;
    const Vec3d centre = lower + size * 0.5;
    std::vector<Line> lines;
    for (int i = 0; i < 4096; ++i) {
        const Vec3d target = lower + Vec3d(unit(random) * size.x, unit(random) * size.y, unit(random) * size.z);
        const Vec3d from = centre + normalize(Vec3d(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5)) * (3 * length(size));
        lines.push_back({Vec3d(Vec3f(from)), Vec3d(Vec3f(normalize(target - from)))});
    }
    return lines;
}

Frustum frustum(double base_radius, double top_radius, bool caps) {
    Frustum f;
    static_cast<AxialFrame&>(f) = AxialFrame::around({0, 0, 0}, normalize(Vec3d(0.2, 1, 0.1)));
    f.height = 2;
    f.base_radius = base_radius;
    f.top_radius = top_radius;
    f.caps = caps;
    return f;
}

Torus torus(double minor) {
    Torus t;
    static_cast<AxialFrame&>(t) = AxialFrame::around({0, 0, 0}, normalize(Vec3d(0.2, 1, 0.1)));
    t.major_radius = 1;
    t.minor_radius = minor;
    return t;
}

std::unique_ptr<Shape> make_shape(int kind) {
    switch (kind) {
        case 0: return std::make_unique<FrustumShape>("cylinder", frustum(1, 1, true));
        case 1: return std::make_unique<FrustumShape>("cylinder", frustum(1, 1, false));
        case 2: return std::make_unique<FrustumShape>("cone", frustum(1, 0, true));
        case 3: return std::make_unique<TorusShape>(torus(0.3));
        case 4: return std::make_unique<TorusShape>(torus(1e-3));
        default: return std::make_unique<SphereShape>(std::vector<Sphere>{{{0, 0, 0}, 1}});
    }
}

const char* kNames[] = {"capped cylinder", "open cylinder", "capped cone", "torus r/R=0.3", "torus r/R=0.001", "sphere (for scale)"};

void solver(benchmark::State& state) {
    const int kind = int(state.range(0));
    const auto shape = make_shape(kind);
    const std::vector<Line> lines = random_lines(shape->bounds());
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        const Line& line = lines[i++ % lines.size()];
        if (const auto* f = dynamic_cast<const FrustumShape*>(shape.get())) {
            const FrustumCrossings c = frustum_crossings(f->frustum(), line.origin, line.direction);
            hits += c.count > 0;
            benchmark::DoNotOptimize(c);
        } else if (const auto* s = dynamic_cast<const SphereShape*>(shape.get())) {
            const auto roots = intersect_sphere(line.origin, line.direction, s->spheres()[0].centre, s->spheres()[0].radius);
            hits += roots.has_value();
            benchmark::DoNotOptimize(roots);
        } else {
            const auto& t = static_cast<const TorusShape&>(*shape).torus();
            const TorusCrossings c = torus_crossings(t, line.origin, line.direction, 0, INFINITY, true);
            hits += c.count > 0;
            benchmark::DoNotOptimize(c);
        }
    }
    state.SetLabel(kNames[kind]);
    state.counters["hit_fraction"] = double(hits) / double(state.iterations());
}

void embree_query(benchmark::State& state) {
    const int kind = int(state.range(0));
    RenderScene scene;
    SceneObject object;
    object.shape = make_shape(kind);
    const std::vector<Line> lines = random_lines(object.shape->bounds());
    scene.add_object(std::move(object));
    scene.commit();
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        const Line& line = lines[i++ % lines.size()];
        Ray ray;
        ray.origin = Vec3f(line.origin);
        ray.direction = Vec3f(line.direction);
        const auto hit = scene.intersect(ray, RayKind::Camera);
        hits += hit.has_value();
        benchmark::DoNotOptimize(hit);
    }
    state.SetLabel(kNames[kind]);
    state.counters["hit_fraction"] = double(hits) / double(state.iterations());
}

BENCHMARK(solver)->DenseRange(0, 5);
BENCHMARK(embree_query)->DenseRange(0, 5);

}  // namespace
}  // namespace isotrace

BENCHMARK_MAIN();
