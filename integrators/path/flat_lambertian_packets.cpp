#include "integrators/path/flat_lambertian_packets.h"

#include <embree3/rtcore.h>

#include <array>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string_view>
#include <utility>

#include "renderer/core/version.h"
#include "renderer/math/lanes.h"
#include "renderer/plugin/shadow_ray.h"
#include "renderer/sampling/sampler.h"
#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

using isotrace::select;  // the lanes' own, beside the overloads for vectors and colours below

// Vectors and colours in lanes. Each operation is the scalar one's, in the scalar one's order (Vec3f and
// Rgb in renderer/math): that is what keeps the lanes' bits those of PathIntegrator::radiance.
struct Vec3Lanes {
    FloatLanes x, y, z;
};
Vec3Lanes operator+(const Vec3Lanes& a, const Vec3Lanes& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3Lanes operator-(const Vec3Lanes& a, const Vec3Lanes& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3Lanes operator-(const Vec3Lanes& a) { return {-a.x, -a.y, -a.z}; }
Vec3Lanes operator*(const Vec3Lanes& a, FloatLanes s) { return {a.x * s, a.y * s, a.z * s}; }
FloatLanes dot(const Vec3Lanes& a, const Vec3Lanes& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
FloatLanes length(const Vec3Lanes& a) { return sqrt(dot(a, a)); }
Vec3Lanes normalize(const Vec3Lanes& a) { return a * (1.0f / length(a)); }
Vec3Lanes select(IntLanes mask, const Vec3Lanes& a, const Vec3Lanes& b) {
    return {select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z)};
}

struct RgbLanes {
    FloatLanes r, g, b;
};
RgbLanes operator*(const RgbLanes& a, const RgbLanes& b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }
RgbLanes operator*(const RgbLanes& a, FloatLanes s) { return {a.r * s, a.g * s, a.b * s}; }
RgbLanes select(IntLanes mask, const RgbLanes& a, const RgbLanes& b) {
    return {select(mask, a.r, b.r), select(mask, a.g, b.g), select(mask, a.b, b.b)};
}
FloatLanes max_channel(const RgbLanes& c) {
    return select(c.r > c.g, select(c.r > c.b, c.r, c.b), select(c.g > c.b, c.g, c.b));
}
IntLanes is_black(const RgbLanes& c) { return (c.r == 0.0f) & (c.g == 0.0f) & (c.b == 0.0f); }

// orthonormal_basis around the unit normal n, and the frame's changes of basis (ShadingFrame).
struct FrameLanes {
    Vec3Lanes tangent, bitangent, normal;

    explicit FrameLanes(const Vec3Lanes& n) : normal(n) {
        const FloatLanes sign = sign_of(n.z);
        const FloatLanes a = -1.0f / (sign + n.z);
        const FloatLanes b = n.x * n.y * a;
        tangent = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
        bitangent = {b, sign + n.y * n.y * a, -n.y};
    }
    Vec3Lanes to_local(const Vec3Lanes& w) const { return {dot(w, tangent), dot(w, bitangent), dot(w, normal)}; }
    Vec3Lanes to_world(const Vec3Lanes& w) const { return tangent * w.x + bitangent * w.y + normal * w.z; }
};

// SurfaceHit::spawn_origin: off the surface along the geometric normal, to the side `direction` leaves on.
Vec3Lanes spawn_origin(const Vec3Lanes& position, const Vec3Lanes& normal, FloatLanes position_error,
                       const Vec3Lanes& direction) {
    const FloatLanes side = select(dot(normal, direction) >= 0.0f, splat(1.0f), splat(-1.0f));
    return position + normal * (side * position_error);
}

// Embree's packets of kLanes rays.
static_assert(kLanes == 8);
using EmbreeRayHits = RTCRayHit8;
using EmbreeRays = RTCRay8;

// Embree's ray layout for the lanes (ids and flags 0, masks all ones, as set_embree_ray writes a single ray).
template <class Rays>
void set_rays(Rays& rays, const Vec3Lanes& origin, const Vec3Lanes& direction, FloatLanes t_near, FloatLanes t_far) {
    store_lanes(rays.org_x, origin.x);
    store_lanes(rays.org_y, origin.y);
    store_lanes(rays.org_z, origin.z);
    store_lanes(rays.dir_x, direction.x);
    store_lanes(rays.dir_y, direction.y);
    store_lanes(rays.dir_z, direction.z);
    store_lanes(rays.tnear, t_near);
    store_lanes(rays.tfar, t_far);
    store_lanes(rays.time, splat(0.0f));
    store_lanes(reinterpret_cast<std::int32_t*>(rays.mask), splat(-1));
    store_lanes(reinterpret_cast<std::int32_t*>(rays.id), splat(0));
    store_lanes(reinterpret_cast<std::int32_t*>(rays.flags), splat(0));
}

// Values written one lane at a time (where a lane may be skipped) go to an array and are loaded as a vector once: a
// lane inserted into a vector in place is a store into it followed by a load of all of it, which waits for the
// store (failed store forwarding) once per lane instead of once per vector. Where every lane is read, lanes_of is
// cheaper still.
struct LaneArrays3 {
    alignas(64) float x[kLanes]{}, y[kLanes]{}, z[kLanes]{};
    void set(std::size_t lane, float a, float b, float c) { x[lane] = a, y[lane] = b, z[lane] = c; }
    Vec3Lanes vec() const { return {load_lanes(x), load_lanes(y), load_lanes(z)}; }
    RgbLanes rgb() const { return {load_lanes(x), load_lanes(y), load_lanes(z)}; }
};

// The live lanes' four random numbers of a bounce, drawn from their own streams in the order and with the blocks
// PathIntegrator::radiance takes them (its comment there tells why two bounces share a block of directions).
struct BounceNumbers {
    FloatLanes light_choice, direction_0, direction_1, roulette;
};
BounceNumbers draw_bounce_numbers(int depth, unsigned live, bool light_choice_is_random, int roulette_depth,
                                  std::span<SampleStream> samples, std::array<Sampler::Block, kLanes>& pair_directions,
                                  std::array<Sampler::Block, kLanes>& pair_roulette) {
    const bool first_of_pair = depth % 2 == 0;
    // The lanes stand at the same dimension (they have taken the same blocks), so each block is drawn for all at once.
    const auto skip = [&] {
        for (std::size_t lane = 0; lane < samples.size(); ++lane)
            if (live >> lane & 1u) samples[lane].skip_block();
    };
    std::array<Sampler::Block, kLanes> light{};
    if (light_choice_is_random)
        SampleStream::next_blocks(samples, live, light);
    else
        skip();
    if (first_of_pair) {
        SampleStream::next_blocks(samples, live, pair_directions);
        pair_roulette = {};
        if (depth + 2 >= roulette_depth)
            SampleStream::next_blocks(samples, live, pair_roulette);
        else
            skip();
    }
    // Into registers lane by lane (dead lanes get stale values that nothing reads).
    const auto dimension = [](const std::array<Sampler::Block, kLanes>& blocks, std::size_t d) {
        return lanes_of([&](std::size_t lane) { return blocks[lane][d]; });
    };
    return {dimension(light, 2), dimension(pair_directions, first_of_pair ? 0 : 2),
            dimension(pair_directions, first_of_pair ? 1 : 3), dimension(pair_roulette, std::size_t(depth % 2))};
}

}  // namespace

// ISOTRACE_PACKETS_ISA names the build: baseline_isa in the library, avx2_isa in the module.
namespace ISOTRACE_PACKETS_ISA {

void trace_flat_lambertian_paths(const PathSettings& settings, std::span<const Ray> camera_rays,
                                 const RenderScene& scene, const FlatLambertianScene& flat,
                                 std::span<SampleStream> samples, std::span<PrimaryHitRecord> primary,
                                 std::span<Rgb> radiance) {
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    constexpr float kInvPi = std::numbers::inv_pi_v<float>;
    const std::size_t count = camera_rays.size();
    const FloatLanes zero = splat(0.0f), one = splat(1.0f);

    alignas(64) std::int32_t valid[kLanes]{};  // the live lanes, as Embree reads them
    LaneArrays3 camera_origin, camera_direction;
    alignas(64) float camera_near[kLanes]{}, camera_far[kLanes]{};
    for (std::size_t lane = 0; lane < count; ++lane) {
        const Ray& ray = camera_rays[lane];
        valid[lane] = -1;
        camera_origin.set(lane, ray.origin.x, ray.origin.y, ray.origin.z);
        camera_direction.set(lane, ray.direction.x, ray.direction.y, ray.direction.z);
        camera_near[lane] = ray.t_near, camera_far[lane] = ray.t_far;
    }
    IntLanes alive = load_lanes(valid);
    Vec3Lanes origin = camera_origin.vec();
    Vec3Lanes direction = normalize(camera_direction.vec());  // hit.t is then a distance, as in the scalar loop
    FloatLanes t_near = load_lanes(camera_near), t_far = load_lanes(camera_far);
    RgbLanes result{zero, zero, zero}, throughput{one, one, one};
    std::array<Sampler::Block, kLanes> pair_directions{}, pair_roulette{};
    const bool light_choice_is_random = !scene.light_sampling_is_deterministic();

    for (int depth = 0;; ++depth) {
        // The nearest hits. A lane that misses ends: nothing at infinity emits in these scenes.
        alignas(64) EmbreeRayHits query;
        set_rays(query.ray, origin, direction, t_near, t_far);
        store_lanes(reinterpret_cast<std::int32_t*>(query.hit.geomID), splat(-1));
        store_lanes(reinterpret_cast<std::int32_t*>(query.hit.instID[0]), splat(-1));
        store_lanes(valid, alive);
        scene.intersect_packet(valid, query, depth == 0 ? RayKind::Camera : RayKind::Secondary);
        alive &= load_lanes(reinterpret_cast<const std::int32_t*>(query.hit.geomID)) != -1;
        if (!any(alive)) break;
        store_lanes(valid, alive);

        // RenderScene::intersect's hit completion for Embree-hit shading: Ng normalised (safe_normalize, falling
        // back to +z), the same normal for shading, the position and its error bound.
        const FloatLanes t = load_lanes(query.ray.tfar);
        const Vec3Lanes embree_ng{load_lanes(query.hit.Ng_x), load_lanes(query.hit.Ng_y), load_lanes(query.hit.Ng_z)};
        const FloatLanes ng_length = sqrt(dot(embree_ng, embree_ng));
        const IntLanes usable = (ng_length > 0.0f) & (ng_length < kInfinity);
        const Vec3Lanes normal = select(usable, embree_ng * (1.0f / ng_length), Vec3Lanes{zero, zero, one});
        const Vec3Lanes position = origin + direction * t;
        const FloatLanes position_error =
            RenderScene::kPositionErrorScale *
            (max(abs(position.x), max(abs(position.y), abs(position.z))) + t * sqrt(dot(direction, direction)));
        // The reflectances, gathered lane by lane into registers (dead lanes read geometry 0's).
        alignas(64) std::int32_t geometry[kLanes];
        store_lanes(geometry, select(alive, load_lanes(reinterpret_cast<const std::int32_t*>(query.hit.geomID)), splat(0)));
        const auto gather = [&](float Rgb::*channel) {
            const auto r = [&](std::size_t lane) {
                return flat.reflectance_of_geometry[std::size_t(geometry[lane])].*channel;
            };
            return lanes_of(r);
        };
        const RgbLanes reflectance{gather(&Rgb::r), gather(&Rgb::g), gather(&Rgb::b)};
        if (depth == 0) {
            for (std::size_t lane = 0; lane < count; ++lane) {
                if (!valid[lane]) continue;
                PrimaryHitRecord& record = primary[lane];  // PrimaryHitRecord::record, the albedo the reflectance
                record.hit = true;
                record.albedo = flat.reflectance_of_geometry[std::size_t(geometry[lane])];
                record.shading_normal = {normal.x[lane], normal.y[lane], normal.z[lane]};
                record.position = {position.x[lane], position.y[lane], position.z[lane]};
                record.object_id = scene.object_of_geometry(unsigned(geometry[lane]));
                record.primitive_id = query.hit.primID[lane];
            }
        }
        if (depth >= settings.max_depth) break;

        const FrameLanes frame(normal);
        const Vec3Lanes wo = frame.to_local(-direction);
        const BounceNumbers numbers = draw_bounce_numbers(depth, lane_bits(alive), light_choice_is_random,
                                                          settings.russian_roulette_depth, samples.first(count),
                                                          pair_directions, pair_roulette);
        const RgbLanes lambert{reflectance.r * kInvPi, reflectance.g * kInvPi, reflectance.b * kInvPi};  // f = R / pi

        // Next-event estimation: one point light per lane, chosen in proportion to power, and its shadow ray.
        if (!flat.lights.empty()) {
            Vec3Lanes light_position;
            RgbLanes intensity;
            FloatLanes choice_probability;
            if (flat.lights.size() == 1) {  // chosen with probability 1 (Distribution1D of one weight)
                const IsotropicPoint& light = flat.lights[0];
                light_position = {splat(light.position.x), splat(light.position.y), splat(light.position.z)};
                intensity = {splat(light.intensity.r), splat(light.intensity.g), splat(light.intensity.b)};
                choice_probability = scene.choose_light(0).probability * one;
            } else {
                LaneArrays3 positions, intensities;
                alignas(64) float probabilities[kLanes], light_choice[kLanes];
                store_lanes(light_choice, numbers.light_choice);
                for (std::size_t lane = 0; lane < std::size_t(kLanes); ++lane) {
                    probabilities[lane] = 1;
                    if (!valid[lane]) continue;
                    const LightChoice choice = scene.choose_light(light_choice[lane]);
                    const IsotropicPoint& light = flat.lights[choice.index];
                    positions.set(lane, light.position.x, light.position.y, light.position.z);
                    intensities.set(lane, light.intensity.r, light.intensity.g, light.intensity.b);
                    probabilities[lane] = choice.probability;
                }
                light_position = positions.vec();
                intensity = intensities.rgb();
                choice_probability = load_lanes(probabilities);
            }
            // IsotropicPoint's sample(): towards the light, the intensity over the squared distance, pdf 1.
            const Vec3Lanes offset = light_position - position;
            const FloatLanes distance_squared = dot(offset, offset);
            const FloatLanes distance = sqrt(distance_squared);
            const Vec3Lanes to_light = offset * (1.0f / distance);
            const RgbLanes incident = intensity * (1.0f / distance_squared);
            const Vec3Lanes wi = frame.to_local(to_light);
            const RgbLanes f_cos = select(wo.z * wi.z > 0.0f, lambert, RgbLanes{zero, zero, zero}) * abs(wi.z);
            const RgbLanes throughput_f = throughput * f_cos;
            const IntLanes shadow =
                alive & ~is_black(incident) & ~is_black(throughput_f) & (dot(to_light, normal) * wi.z > 0.0f);
            if (any(shadow)) {
                alignas(64) EmbreeRays shadow_rays;
                // A point light's distance is finite where its incident light is not black: no lane is at infinity.
                const Vec3Lanes shadow_origin = spawn_origin(position, normal, position_error, to_light);
                const ShadowSegment<Vec3Lanes, FloatLanes> segment =
                    shadow_segment(position, shadow_origin, to_light, distance);
                set_rays(shadow_rays, shadow_origin, segment.direction, zero, segment.t_far);
                store_lanes(valid, shadow);
                scene.occluded_packet(valid, shadow_rays);
                const IntLanes lit = shadow & (load_lanes(shadow_rays.tfar) != -kInfinity);
                // weight 1 (a delta light) over the light's pdf (the choice's probability times 1)
                const RgbLanes value = (throughput_f * incident) * (1.0f / (choice_probability * 1.0f));
                RgbLanes added = value;
                if (settings.clamp > 0) {
                    const FloatLanes peak = max_channel(value);
                    added = select(peak > settings.clamp, value * (settings.clamp / peak), value);
                }
                result = select(lit, RgbLanes{result.r + added.r, result.g + added.g, result.b + added.b}, result);
            }
        }

        // The next ray could only find emission, and nothing here emits.
        if (depth + 1 >= settings.max_depth) break;

        // A cosine-distributed bounce (LambertBsdf through TwoSidedBsdf: sampled on wo's side, mirrored back).
        IntLanes scatters = alive & (wo.z != 0.0f);
        const IntLanes below = wo.z < 0.0f;
        const FloatLanes upper_wo_z = select(below, -wo.z, wo.z);
        FloatLanes disk_x, disk_y;
        concentric_disk_point(2.0f * numbers.direction_0 - 1.0f, 2.0f * numbers.direction_1 - 1.0f, disk_x, disk_y);
        const FloatLanes upper_wi_z = sqrt(max(zero, 1.0f - disk_x * disk_x - disk_y * disk_y));
        const FloatLanes pdf = select((upper_wo_z * upper_wi_z > 0.0f) & (upper_wi_z > 0.0f),
                                  upper_wi_z / std::numbers::pi_v<float>, zero);
        scatters &= pdf > 0.0f;
        const RgbLanes weight = lambert * (abs(upper_wi_z) / pdf);
        scatters &= ~is_black(weight);
        const FloatLanes wi_z = select(below, -upper_wi_z, upper_wi_z);
        const Vec3Lanes bounce = normalize(frame.to_world({disk_x, disk_y, wi_z}));
        scatters &= dot(bounce, normal) * wi_z > 0.0f;
        throughput = throughput * weight;
        scatters &= ~is_black(throughput);
        if (depth + 1 >= settings.russian_roulette_depth) {
            const FloatLanes survival = min(one, max_channel(throughput) * 1.0f);  // times eta_scale: no refraction here
            scatters &= numbers.roulette < survival;
            throughput = throughput * (1.0f / survival);
        }
        alive = scatters;
        if (!any(alive)) break;
        origin = spawn_origin(position, normal, position_error, bounce);
        direction = bounce;
        t_near = zero;
        t_far = splat(kInfinity);
    }
    for (std::size_t lane = 0; lane < count; ++lane) radiance[lane] = {result.r[lane], result.g[lane], result.b[lane]};
}

}  // namespace ISOTRACE_PACKETS_ISA

#ifdef ISOTRACE_PACKETS_MODULE
extern "C" [[gnu::visibility("default")]] FlatLambertianKernel isotrace_flat_lambertian_kernel(const char* version) {
    return std::string_view(version) == kIsotraceVersion ? &ISOTRACE_PACKETS_ISA::trace_flat_lambertian_paths : nullptr;
}
#endif

}  // namespace isotrace
