// Geometry: a random sphere, box, superquadric (with taper, twist, bend), CSG of two of them, or blob group of
// metaballs and metacubes (any kernel, negative weights too), loaded through the scene loader (blob groups only
// through their public scene form), then random rays.
// Invariants: no NaN; a hit lies inside (t_near, t_far); unit normals; occlusion agrees with intersection; and the
// work per ray is bounded: the geometry's own work counters (root-finder and search steps, sweep pieces, CSG
// events) for one ray's intersect() and occluded() stay below kWorkPerPrimitive per primitive of the configuration.
// The bound is deterministic (no clock, so it cannot flake on a loaded machine); libFuzzer's -timeout is the
// wall-clock backstop for loops that count nothing.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "renderer/core/input_error.h"
#include "renderer/core/render_counters.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/fuzz/fuzz_input_file.h"

namespace {

// Work units per ray and primitive. A blob ray costs a few cell queries of a few candidates, pieces and root steps
// each (isotrace render --stats counts them), a superquadric ray tens to hundreds of search steps; the cap is about
// a thousand times that, so only a runaway loop reaches it.
constexpr std::uint64_t kWorkPerPrimitive = 100'000;

// The counters that count the steps of every input-dependent loop along a ray.
constexpr const char* kWorkCounters[] = {
    "blobs.candidates", "blobs.pieces", "blobs.root_iterations", "superquadric.interval_bounds",
    "superquadric.evaluations", "csg.span_events"};

std::uint64_t ray_work() {
    const auto named = isotrace::counters::totals().named;
    std::uint64_t work = 0;
    for (const char* name : kWorkCounters)
        if (const auto found = named.find(name); found != named.end()) work += found->second;
    return work;
}

std::string number(FuzzedDataProvider& in, double low, double high) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", in.ConsumeFloatingPointInRange(low, high));
    return text;
}

std::string vec3(FuzzedDataProvider& in, double low, double high) {
    return "[" + number(in, low, high) + ", " + number(in, low, high) + ", " + number(in, low, high) + "]";
}

std::string superquadric(FuzzedDataProvider& in) {
    std::string shape = R"({"type": "superquadric", "radii": )" + vec3(in, 0.05, 2) + R"(, "exponents": [)" +
                        number(in, 0.1, 3) + ", " + number(in, 0.1, 3) + R"(], "deform": [)";
    const int stages = in.ConsumeIntegralInRange(0, 3);
    for (int i = 0; i < stages; ++i) {
        if (i > 0) shape += ", ";
        switch (in.ConsumeIntegralInRange(0, 2)) {
            case 0: shape += R"({"taper": )" + number(in, -0.9, 0.9) + "}"; break;
            case 1: shape += R"({"twist": )" + number(in, -720, 720) + "}"; break;
            default:
                shape += R"({"bend": {"curvature": )" + number(in, 0, 1) + R"(, "direction": )" + number(in, 0, 360) + "}}";
        }
    }
    return shape + "]}";
}

std::string solid(FuzzedDataProvider& in, std::uint64_t& primitives) {
    ++primitives;
    switch (in.ConsumeIntegralInRange(0, 2)) {
        case 0: return R"({"type": "sphere", "center": )" + vec3(in, -1, 1) + R"(, "radius": )" + number(in, 0.05, 2) + "}";
        case 1: return R"({"type": "box", "center": )" + vec3(in, -1, 1) + R"(, "half_size": )" + vec3(in, 0.05, 2) + "}";
        default: return superquadric(in);
    }
}

std::string shape(FuzzedDataProvider& in, std::uint64_t& primitives) {
    switch (in.ConsumeIntegralInRange(0, 2)) {
        case 0: return solid(in, primitives);
        case 1: {
            static const char* const kOps[] = {"union", "intersection", "difference"};
            const std::string op = kOps[in.ConsumeIntegralInRange(0, 2)];
            const std::string first = solid(in, primitives), second = solid(in, primitives);
            return R"({"type": "csg", "op": ")" + op + R"(", "children": [{"shape": )" + first + R"(}, {"shape": )" +
                   second + "}]}";
        }
        default: {
            static const char* const kFields[] = {"kim", "wyvill", "murakami", "nishimura", "blinn"};
            const std::string field = kFields[in.ConsumeIntegralInRange(0, 4)];
            std::string elements;
            const int count = in.ConsumeIntegralInRange(1, 12);
            primitives += std::uint64_t(count);
            for (int i = 0; i < count; ++i) {
                elements += std::string(i ? ", " : "") + R"({"center": )" + vec3(in, -1.5, 1.5) + R"(, "radius": )" +
                            number(in, 0.1, 1.5) + R"(, "weight": )" + number(in, -1, 2);
                if (in.ConsumeBool()) elements += R"(, "half_size": )" + vec3(in, 0, 1);  // a metacube
                elements += "}";
            }
            return R"({"type": "blobs", "field": ")" + field + R"(", "elements": [)" + elements + "]}";
        }
    }
}

[[noreturn]] void violated(const char* what, const isotrace::Ray& ray, const std::string& scene) {
    std::fprintf(stderr, "invariant violated: %s\nray origin (%g %g %g) direction (%g %g %g) t [%g, %g]\nscene: %s\n",
                 what, ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z,
                 ray.t_near, ray.t_far, scene.c_str());
    std::abort();
}

bool finite(const isotrace::Vec3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace isotrace;
    FuzzedDataProvider in(data, size);
    std::uint64_t primitives = 0;
    const std::string scene = R"({"isotrace": 1, "film": {"resolution": [4, 4], "spp": 1}, "camera": {"type": )"
                              R"("perspective", "look_at": {"eye": [0, 0, -5], "target": [0, 0, 0], "up": [0, 1, 0]}},)"
                              R"( "materials": {"m": {"type": "diffuse"}}, "objects": [{"material": "m", "shape": )" +
                              shape(in, primitives) + "}]}";
    std::unique_ptr<LoadedScene> loaded;
    try {
        const std::string text = scene;
        loaded = load_scene(fuzz::write_input(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), ".json"));
    } catch (const InputError&) {
        return 0;  // a configuration the loader rejects with a message is fine
    }
    for (int i = 0; i < 16 && in.remaining_bytes() > 0; ++i) {
        Ray ray;
        ray.origin = Vec3f(in.ConsumeFloatingPointInRange(-4.0f, 4.0f), in.ConsumeFloatingPointInRange(-4.0f, 4.0f),
                           in.ConsumeFloatingPointInRange(-4.0f, 4.0f));
        Vec3f d(in.ConsumeFloatingPointInRange(-1.0f, 1.0f), in.ConsumeFloatingPointInRange(-1.0f, 1.0f),
                in.ConsumeFloatingPointInRange(-1.0f, 1.0f));
        if (!(length(d) > 1e-3f)) continue;
        ray.direction = normalize(d);
        ray.t_near = in.ConsumeFloatingPointInRange(0.0f, 1.0f);
        ray.t_far = in.ConsumeBool() ? INFINITY : ray.t_near + in.ConsumeFloatingPointInRange(0.0f, 10.0f);
        counters::reset();
        const auto hit = loaded->scene->intersect(ray, RayKind::Camera);
        const bool blocked = loaded->scene->occluded(ray);
        const std::uint64_t work = ray_work();
        if (work > kWorkPerPrimitive * primitives) {
            std::fprintf(stderr, "work %llu for %llu primitives\n", static_cast<unsigned long long>(work),
                         static_cast<unsigned long long>(primitives));
            violated("work per ray above the bound", ray, scene);
        }
        if (hit) {
            if (!std::isfinite(hit->t) || !finite(hit->position)) violated("non-finite hit", ray, scene);
            if (!(hit->t >= ray.t_near && hit->t <= ray.t_far)) violated("hit outside [t_near, t_far]", ray, scene);
            if (std::abs(length(hit->geometric_normal) - 1) > 1e-3f) violated("geometric normal not unit", ray, scene);
            if (std::abs(length(hit->shading_normal) - 1) > 1e-3f) violated("shading normal not unit", ray, scene);
        }
        if (blocked != hit.has_value()) violated("occluded() disagrees with intersect()", ray, scene);
    }
    return 0;
}
