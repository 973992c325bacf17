#include "integrators/path/flat_lambertian_packets.h"

#include <embree3/rtcore.h>

#include <array>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string_view>

#include "renderer/core/version.h"
#include "renderer/math/lanes8.h"
#include "renderer/sampling/sampler.h"
#include "renderer/sampling/warps.h"

namespace isotrace {
namespace {

using isotrace::select;  // the lanes' own, beside the overloads for vectors and colours below

// Vectors and colours of eight lanes. Each operation is the scalar one's, in the scalar one's order (Vec3f and
// Rgb in renderer/math): that is what keeps the lanes' bits those of PathIntegrator::radiance.
struct Vec3x8 {
    Float8 x, y, z;
};
Vec3x8 operator+(const Vec3x8& a, const Vec3x8& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3x8 operator-(const Vec3x8& a, const Vec3x8& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3x8 operator-(const Vec3x8& a) { return {-a.x, -a.y, -a.z}; }
Vec3x8 operator*(const Vec3x8& a, Float8 s) { return {a.x * s, a.y * s, a.z * s}; }
Float8 dot(const Vec3x8& a, const Vec3x8& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3x8 normalize(const Vec3x8& a) { return a * (1.0f / sqrt(dot(a, a))); }
Vec3x8 select(Int8 mask, const Vec3x8& a, const Vec3x8& b) {
    return {select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z)};
}

struct Rgb8 {
    Float8 r, g, b;
};
Rgb8 operator*(const Rgb8& a, const Rgb8& b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }
Rgb8 operator*(const Rgb8& a, Float8 s) { return {a.r * s, a.g * s, a.b * s}; }
Rgb8 select(Int8 mask, const Rgb8& a, const Rgb8& b) {
    return {select(mask, a.r, b.r), select(mask, a.g, b.g), select(mask, a.b, b.b)};
}
Float8 max_channel(const Rgb8& c) { return select(c.r > c.g, select(c.r > c.b, c.r, c.b), select(c.g > c.b, c.g, c.b)); }
Int8 is_black(const Rgb8& c) { return (c.r == 0.0f) & (c.g == 0.0f) & (c.b == 0.0f); }

// orthonormal_basis around the unit normal n, and the frame's changes of basis (ShadingFrame).
struct Frame8 {
    Vec3x8 tangent, bitangent, normal;

    explicit Frame8(const Vec3x8& n) : normal(n) {
        const Float8 sign = sign_of(n.z);
        const Float8 a = -1.0f / (sign + n.z);
        const Float8 b = n.x * n.y * a;
        tangent = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
        bitangent = {b, sign + n.y * n.y * a, -n.y};
    }
    Vec3x8 to_local(const Vec3x8& w) const { return {dot(w, tangent), dot(w, bitangent), dot(w, normal)}; }
    Vec3x8 to_world(const Vec3x8& w) const { return tangent * w.x + bitangent * w.y + normal * w.z; }
};

// SurfaceHit::spawn_origin: off the surface along the geometric normal, to the side `direction` leaves on.
Vec3x8 spawn_origin(const Vec3x8& position, const Vec3x8& normal, Float8 position_error, const Vec3x8& direction) {
    const Float8 side = select(dot(normal, direction) >= 0.0f, splat8(1.0f), splat8(-1.0f));
    return position + normal * (side * position_error);
}

// Embree's ray layout for the lanes (ids and flags 0, masks all ones, as set_embree_ray writes a single ray).
template <class Rays>
void set_rays(Rays& rays, const Vec3x8& origin, const Vec3x8& direction, Float8 t_near, Float8 t_far) {
    store8(rays.org_x, origin.x);
    store8(rays.org_y, origin.y);
    store8(rays.org_z, origin.z);
    store8(rays.dir_x, direction.x);
    store8(rays.dir_y, direction.y);
    store8(rays.dir_z, direction.z);
    store8(rays.tnear, t_near);
    store8(rays.tfar, t_far);
    store8(rays.time, splat8(0.0f));
    store8(reinterpret_cast<std::int32_t*>(rays.mask), splat8(-1));
    store8(reinterpret_cast<std::int32_t*>(rays.id), splat8(0));
    store8(reinterpret_cast<std::int32_t*>(rays.flags), splat8(0));
}

// Values written one lane at a time go to an array and are loaded as a vector once: a lane inserted into a vector
// in place is a store into it followed by a load of all of it, which waits for the store (failed store forwarding).
struct LaneArrays3 {
    alignas(32) float x[8]{}, y[8]{}, z[8]{};
    void set(std::size_t lane, float a, float b, float c) { x[lane] = a, y[lane] = b, z[lane] = c; }
    Vec3x8 vec() const { return {load8(x), load8(y), load8(z)}; }
    Rgb8 rgb() const { return {load8(x), load8(y), load8(z)}; }
};

// The live lanes' four random numbers of a bounce, drawn from their own streams in the order and with the blocks
// PathIntegrator::radiance takes them (its comment there tells why two bounces share a block of directions).
struct BounceNumbers {
    Float8 light_choice, direction_0, direction_1, roulette;
};
BounceNumbers draw_bounce_numbers(int depth, unsigned live, bool light_choice_is_random, int roulette_depth,
                                  std::span<SampleStream> samples, std::array<Sampler::Block, 8>& pair_directions,
                                  std::array<Sampler::Block, 8>& pair_roulette) {
    const bool first_of_pair = depth % 2 == 0;
    // The lanes stand at the same dimension (they have taken the same blocks), so each block is drawn for all at once.
    const auto skip = [&] {
        for (std::size_t lane = 0; lane < samples.size(); ++lane)
            if (live >> lane & 1u) samples[lane].skip_block();
    };
    std::array<Sampler::Block, 8> light{};
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
    const auto dimension = [](const std::array<Sampler::Block, 8>& blocks, std::size_t d) {
        return Float8{blocks[0][d], blocks[1][d], blocks[2][d], blocks[3][d],
                      blocks[4][d], blocks[5][d], blocks[6][d], blocks[7][d]};
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
    const Float8 zero = splat8(0.0f), one = splat8(1.0f);

    alignas(32) std::int32_t valid[8]{};  // the live lanes, as Embree reads them
    LaneArrays3 camera_origin, camera_direction;
    alignas(32) float camera_near[8]{}, camera_far[8]{};
    for (std::size_t lane = 0; lane < count; ++lane) {
        const Ray& ray = camera_rays[lane];
        valid[lane] = -1;
        camera_origin.set(lane, ray.origin.x, ray.origin.y, ray.origin.z);
        camera_direction.set(lane, ray.direction.x, ray.direction.y, ray.direction.z);
        camera_near[lane] = ray.t_near, camera_far[lane] = ray.t_far;
    }
    Int8 alive = load8(valid);
    Vec3x8 origin = camera_origin.vec();
    Vec3x8 direction = normalize(camera_direction.vec());  // hit.t is then a distance, as in the scalar loop
    Float8 t_near = load8(camera_near), t_far = load8(camera_far);
    Rgb8 result{zero, zero, zero}, throughput{one, one, one};
    std::array<Sampler::Block, 8> pair_directions{}, pair_roulette{};
    const bool light_choice_is_random = !scene.light_sampling_is_deterministic();

    for (int depth = 0;; ++depth) {
        // The nearest hits. A lane that misses ends: nothing at infinity emits in these scenes.
        alignas(32) RTCRayHit8 query;
        set_rays(query.ray, origin, direction, t_near, t_far);
        store8(reinterpret_cast<std::int32_t*>(query.hit.geomID), splat8(-1));
        store8(reinterpret_cast<std::int32_t*>(query.hit.instID[0]), splat8(-1));
        store8(valid, alive);
        scene.intersect8(valid, query, depth == 0 ? RayKind::Camera : RayKind::Secondary);
        alive &= load8(reinterpret_cast<const std::int32_t*>(query.hit.geomID)) != -1;
        if (!any(alive)) break;
        store8(valid, alive);

        // RenderScene::intersect's hit completion for Embree-hit shading: Ng normalised (safe_normalize, falling
        // back to +z), the same normal for shading, the position and its error bound.
        const Float8 t = load8(query.ray.tfar);
        const Vec3x8 embree_ng{load8(query.hit.Ng_x), load8(query.hit.Ng_y), load8(query.hit.Ng_z)};
        const Float8 ng_length = sqrt(dot(embree_ng, embree_ng));
        const Int8 usable = (ng_length > 0.0f) & (ng_length < kInfinity);
        const Vec3x8 normal = select(usable, embree_ng * (1.0f / ng_length), Vec3x8{zero, zero, one});
        const Vec3x8 position = origin + direction * t;
        const Float8 position_error =
            RenderScene::kPositionErrorScale *
            (max(abs(position.x), max(abs(position.y), abs(position.z))) + t * sqrt(dot(direction, direction)));
        // The reflectances, gathered lane by lane into registers (dead lanes read geometry 0's).
        alignas(32) std::int32_t geometry[8];
        store8(geometry, select(alive, load8(reinterpret_cast<const std::int32_t*>(query.hit.geomID)), splat8(0)));
        const auto gather = [&](float Rgb::*channel) {
            const auto r = [&](int lane) { return flat.reflectance_of_geometry[std::size_t(geometry[lane])].*channel; };
            return Float8{r(0), r(1), r(2), r(3), r(4), r(5), r(6), r(7)};
        };
        const Rgb8 reflectance{gather(&Rgb::r), gather(&Rgb::g), gather(&Rgb::b)};
        if (depth == 0) {
            for (std::size_t lane = 0; lane < count; ++lane) {
                if (!valid[lane]) continue;
                PrimaryHitRecord& record = primary[lane];  // PrimaryHitRecord::record, the albedo the reflectance
                record.hit = true;
                record.albedo = flat.reflectance_of_geometry[std::size_t(geometry[lane])];
                record.shading_normal = {normal.x[lane], normal.y[lane], normal.z[lane]};
                record.position = {position.x[lane], position.y[lane], position.z[lane]};
                record.object_id = flat.object_of_geometry[std::size_t(geometry[lane])];
                record.primitive_id = query.hit.primID[lane];
            }
        }
        if (depth >= settings.max_depth) break;

        const Frame8 frame(normal);
        const Vec3x8 wo = frame.to_local(-direction);
        const BounceNumbers numbers = draw_bounce_numbers(depth, lane_bits(alive), light_choice_is_random,
                                                          settings.russian_roulette_depth, samples.first(count),
                                                          pair_directions, pair_roulette);
        const Rgb8 lambert{reflectance.r * kInvPi, reflectance.g * kInvPi, reflectance.b * kInvPi};  // f = R / pi

        // Next-event estimation: one point light per lane, chosen in proportion to power, and its shadow ray.
        if (!flat.lights.empty()) {
            Vec3x8 light_position;
            Rgb8 intensity;
            Float8 choice_probability;
            if (flat.lights.size() == 1) {  // chosen with probability 1 (Distribution1D of one weight)
                const IsotropicPoint& light = flat.lights[0];
                light_position = {splat8(light.position.x), splat8(light.position.y), splat8(light.position.z)};
                intensity = {splat8(light.intensity.r), splat8(light.intensity.g), splat8(light.intensity.b)};
                choice_probability = scene.choose_light(0).probability * one;
            } else {
                LaneArrays3 positions, intensities;
                alignas(32) float probabilities[8], light_choice[8];
                store8(light_choice, numbers.light_choice);
                for (std::size_t lane = 0; lane < 8; ++lane) {
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
                choice_probability = load8(probabilities);
            }
            // IsotropicPoint's sample(): towards the light, the intensity over the squared distance, pdf 1.
            const Vec3x8 offset = light_position - position;
            const Float8 distance_squared = dot(offset, offset);
            const Float8 distance = sqrt(distance_squared);
            const Vec3x8 to_light = offset * (1.0f / distance);
            const Rgb8 incident = intensity * (1.0f / distance_squared);
            const Vec3x8 wi = frame.to_local(to_light);
            const Rgb8 f_cos = select(wo.z * wi.z > 0.0f, lambert, Rgb8{zero, zero, zero}) * abs(wi.z);
            const Rgb8 throughput_f = throughput * f_cos;
            const Int8 shadow = alive & ~is_black(incident) & ~is_black(throughput_f) & (dot(to_light, normal) * wi.z > 0.0f);
            if (any(shadow)) {
                alignas(32) RTCRay8 shadow_rays;
                const Float8 shadow_far = select(distance == kInfinity, distance, distance * (1 - 1e-4f));
                set_rays(shadow_rays, spawn_origin(position, normal, position_error, to_light), to_light, zero, shadow_far);
                store8(valid, shadow);
                scene.occluded8(valid, shadow_rays);
                const Int8 lit = shadow & (load8(shadow_rays.tfar) != -kInfinity);
                // weight 1 (a delta light) over the light's pdf (the choice's probability times 1)
                const Rgb8 value = (throughput_f * incident) * (1.0f / (choice_probability * 1.0f));
                Rgb8 added = value;
                if (settings.clamp > 0) {
                    const Float8 peak = max_channel(value);
                    added = select(peak > settings.clamp, value * (settings.clamp / peak), value);
                }
                result = select(lit, Rgb8{result.r + added.r, result.g + added.g, result.b + added.b}, result);
            }
        }

        // The next ray could only find emission, and nothing here emits.
        if (depth + 1 >= settings.max_depth) break;

        // A cosine-distributed bounce (LambertBsdf through TwoSidedBsdf: sampled on wo's side, mirrored back).
        Int8 scatters = alive & (wo.z != 0.0f);
        const Int8 below = wo.z < 0.0f;
        const Float8 upper_wo_z = select(below, -wo.z, wo.z);
        Float8 disk_x, disk_y;
        concentric_disk_point(2.0f * numbers.direction_0 - 1.0f, 2.0f * numbers.direction_1 - 1.0f, disk_x, disk_y);
        const Float8 upper_wi_z = sqrt(max(zero, 1.0f - disk_x * disk_x - disk_y * disk_y));
        const Float8 pdf = select((upper_wo_z * upper_wi_z > 0.0f) & (upper_wi_z > 0.0f),
                                  upper_wi_z / std::numbers::pi_v<float>, zero);
        scatters &= pdf > 0.0f;
        const Rgb8 weight = lambert * (abs(upper_wi_z) / pdf);
        scatters &= ~is_black(weight);
        const Float8 wi_z = select(below, -upper_wi_z, upper_wi_z);
        const Vec3x8 bounce = normalize(frame.to_world({disk_x, disk_y, wi_z}));
        scatters &= dot(bounce, normal) * wi_z > 0.0f;
        throughput = throughput * weight;
        scatters &= ~is_black(throughput);
        if (depth + 1 >= settings.russian_roulette_depth) {
            const Float8 survival = min(one, max_channel(throughput) * 1.0f);  // times eta_scale: no refraction here
            scatters &= numbers.roulette < survival;
            throughput = throughput * (1.0f / survival);
        }
        alive = scatters;
        if (!any(alive)) break;
        origin = spawn_origin(position, normal, position_error, bounce);
        direction = bounce;
        t_near = zero;
        t_far = splat8(kInfinity);
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
