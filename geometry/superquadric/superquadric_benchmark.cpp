// What a superquadric costs by exponent class, in the unit its searches are made of: one value of the gauge G at a
// point (the nested p-norm: a power and a root per norm; closed forms for ε = 1 and 2, repeated squaring for whole
// 2/ε, polynomials for fractional ones), then whole queries of the three kinds `isotrace bench` times — a camera ray's
// nearest crossing, a shadow ray leaving the surface (an occlusion query toward a light above), a bounce ray leaving
// it (nearest crossing, cosine-distributed) — with the gauge values each took. The rays leave the surface as the
// bench's do: pushed off along the normal by a thousandth of the shape's size. Twisted, bent and tapered shapes go
// through the surface shell (the shell is filled by the warm-up, as a long render fills it).
// Run: cmake --build build --target superquadric_benchmark && build/bin/superquadric_benchmark
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/superquadric/superquadric.h"

namespace isotrace {
namespace {

struct Case {
    const char* label;
    double north_south, east_west;
    double twist_degrees = 0, bend_curvature = 0, taper_rate = 0;
};

// Undeformed, from the closed form to the fractional exponents; then deformed ones as the benchmark scenes deform
// them.
constexpr std::array<Case, 11> kCases{{
    {"ellipsoid e=(1,1)", 1, 1},
    {"box-like e=(0.05,0.05), whole p=40", 0.05, 0.05},
    {"rounded box e=(0.3,0.3), fractional p", 0.3, 0.3},
    {"octahedron e=(2,2)", 2, 2},
    {"star-like e=(2.5,2.5)", 2.5, 2.5},
    {"mixed e=(0.05,2.5)", 0.05, 2.5},
    {"mixed e=(2.5,1)", 2.5, 1},
    {"star-like e=(2.5,2.5) twisted 90 degrees", 2.5, 2.5, 90, 0},
    {"star-like e=(2.5,2.5) bent, k=0.8", 2.5, 2.5, 0, 0.8},
    {"rounded box e=(0.3,0.3) tapered -0.6", 0.3, 0.3, 0, 0, -0.6},
    {"star-like e=(2.5,2.5) tapered -0.6", 2.5, 2.5, 0, 0, -0.6},
}};

constexpr double kRadius = 0.4;

Superquadric make(const Case& c) {
    const Superellipsoid shape({kRadius, kRadius, kRadius}, c.north_south, c.east_west);
    DeformationChain chain(shape);
    if (c.taper_rate != 0) chain.append(Taper(c.taper_rate, c.taper_rate, kRadius));
    if (c.twist_degrees != 0) chain.append(Twist(c.twist_degrees * std::numbers::pi / 180 / (2 * kRadius), kRadius));
    if (c.bend_curvature != 0) chain.append(Bend(c.bend_curvature, 0, 0, {-kRadius, kRadius}));
    return Superquadric(shape, std::move(chain), Transform::rotate({0.3, 1, 0.2}, 40));
}

struct Ray {
    Vec3d origin, direction;
    double t_max;
};

struct Rays {
    std::vector<Ray> camera, shadow, bounce;
};

// Camera rays from one eye at random points of the box's silhouette plane; shadow and bounce rays from the surface
// points they hit that face the light.
Rays make_rays(const Superquadric& s) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1, 1), half(0, 1);
    const Vec3d eye(0.3, 0.6, 6), light(0.5, 8, 1);
    Rays rays;
    for (int i = 0; i < 4096; ++i) {
        const Vec3d target(unit(random) * 1.5 * kRadius, unit(random) * 1.5 * kRadius, 0);
        const Vec3d direction = normalize(target - eye);
        rays.camera.push_back({eye, direction, 100});
        SuperquadricWork work;
        const std::optional<double> t = s.first_crossing(eye, direction, 0, 100, work);
        if (!t) continue;
        const Vec3d hit = eye + direction * *t, normal = s.normal(hit);
        if (!is_finite(normal) || dot(normal, direction) > 0) continue;
        const Vec3d origin = hit + normal * (1e-3 * 2 * kRadius);
        const Vec3d to_light = light - origin;
        if (dot(to_light, normal) > 0) rays.shadow.push_back({origin, normalize(to_light), length(to_light)});
        // Cosine-distributed about the normal.
        Vec3d tangent, bitangent;
        orthonormal_basis(normal, tangent, bitangent);
        const double r = std::sqrt(half(random)), phi = 2 * std::numbers::pi * half(random);
        const double x = r * std::cos(phi), y = r * std::sin(phi), z = std::sqrt(std::max(0.0, 1 - x * x - y * y));
        rays.bounce.push_back({origin, normalize(tangent * x + bitangent * y + normal * z), 100});
    }
    return rays;
}

void report(benchmark::State& state, const SuperquadricWork& work, double answered) {
    const double queries = double(state.iterations());
    state.SetLabel(kCases[std::size_t(state.range(0))].label);
    state.counters["gauge_values"] = double(work.point_values) / queries;
    state.counters["interval_bounds"] = double(work.search.interval_bounds) / queries;
    state.counters["halvings"] = double(work.search.halvings) / queries;
    state.counters["answered"] = answered / queries;  // hit or blocked
}

// The unit of work: one value of the gauge at a random point of the box.
void gauge_value(benchmark::State& state) {
    const Case& c = kCases[std::size_t(state.range(0))];
    const Superellipsoid shape({kRadius, kRadius, kRadius}, c.north_south, c.east_west);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(-kRadius, kRadius);
    std::vector<Vec3d> points(4096);
    for (Vec3d& p : points) p = {unit(random), unit(random), unit(random)};
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(shape.gauge(points[i++ % points.size()]));
    state.SetLabel(c.label);
}

template <class Query>
void queries(benchmark::State& state, const std::vector<Ray> Rays::*kind, const Query& query) {
    const Superquadric s = make(kCases[std::size_t(state.range(0))]);
    const std::vector<Ray> rays = make_rays(s).*kind;
    SuperquadricWork warm_up;
    for (const Ray& ray : rays) query(s, ray, warm_up);
    SuperquadricWork work;
    double answered = 0;
    std::size_t i = 0;
    for (auto _ : state) answered += query(s, rays[i++ % rays.size()], work);
    report(state, work, answered);
}

bool nearest(const Superquadric& s, const Ray& ray, SuperquadricWork& work) {
    return s.first_crossing(ray.origin, ray.direction, 0, ray.t_max, work).has_value();
}

void camera_ray(benchmark::State& state) { queries(state, &Rays::camera, nearest); }
void bounce_ray(benchmark::State& state) { queries(state, &Rays::bounce, nearest); }
void shadow_ray(benchmark::State& state) {
    queries(state, &Rays::shadow, [](const Superquadric& s, const Ray& ray, SuperquadricWork& work) {
        return s.blocks(ray.origin, ray.direction, 0, float(ray.t_max), work);
    });
}

BENCHMARK(gauge_value)->DenseRange(0, 6);
BENCHMARK(camera_ray)->DenseRange(0, int(kCases.size()) - 1);
BENCHMARK(shadow_ray)->DenseRange(0, int(kCases.size()) - 1);
BENCHMARK(bounce_ray)->DenseRange(0, int(kCases.size()) - 1);

}  // namespace
}  // namespace isotrace

BENCHMARK_MAIN();
