#include "integrators/path/path_integrator.h"

#include <bit>
#include <cmath>
#include <limits>

#include "renderer/bsdf/shading_frame.h"
#include "renderer/bsdf/surface_bsdf.h"
#include "renderer/math/lanes.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/shadow_ray.h"
#include "renderer/sampling/sampler.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {
namespace {

float power_heuristic(float pdf_a, float pdf_b) {
    const float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    return a + b > 0 ? a / (a + b) : 0.0f;
}

// Shading normals bend the hemisphere: a direction the BSDF treats as above the surface may be below the true
// (geometric) surface, which would leak light through it. Accept a direction only when both normals agree.
bool sides_agree(const Vec3f& world_direction, const Vec3f& geometric_normal, float local_z) {
    return dot(world_direction, geometric_normal) * local_z > 0;
}

// The footprint cone of a scattered ray: a mirror or a refraction keeps the incoming spread (the surface's curvature
// is ignored); a rough lobe spreads the ray over about the solid angle 1/pdf around the sampled direction.
float scattered_cone_spread(float incoming_spread, const BsdfSample& scattered) {
    if (scattered.is_delta) return incoming_spread;
    return std::max(incoming_spread, 1.0f / std::sqrt(scattered.pdf));
}

class Contributions {
public:
    Contributions(Rgb& total, float clamp) : total_(total), clamp_(clamp) {}
    void add(const Rgb& value) {
        const float peak = value.max();
        total_ += clamp_ > 0 && peak > clamp_ ? value * (clamp_ / peak) : value;
    }

private:
    Rgb& total_;
    float clamp_;
};

}  // namespace

// A path between its rays (which the caller keeps, so that a packet's rays lie side by side): what it has gathered,
// what it carries, and whether its last bounce cast a shadow ray, with the light that ray brings unless blocked.
struct PathIntegrator::Path {
    Rgb result;
    Rgb throughput{1.0f};
    float eta_scale = 1;  // undoes the radiance scaling of refraction for Russian roulette
    bool previous_was_delta = true;  // camera rays and delta bounces: no MIS on emitter hits
    float previous_pdf = 0;
    Vec3f previous_point;
    Sampler::Block pair_directions{}, pair_roulette{};  // of the current pair of bounces (below)
    int depth = 0;
    bool casts_shadow = false;
    Rgb unblocked;  // the contribution the shadow ray brings if nothing blocks it

    // Starts the path along `camera_ray`, made its first ray.
    explicit Path(Ray& camera_ray) : previous_point(camera_ray.origin) {
        camera_ray.direction = normalize(camera_ray.direction);  // hit.t is then a distance (needed for light pdfs)
    }
};

// Flattened: as a function of its own the bounce kept its small helpers (the shadow ray, the spawn point, the
// shading frame) as calls, which the one-path loop had inlined; inlined again, it costs 2.7 % fewer instructions per
// sample on the box with a speck and 2.0 % on the Cornell box.
[[gnu::flatten]] bool PathIntegrator::bounce(Path& path, Ray& ray, Ray& shadow, const std::optional<SurfaceHit>& found,
                            const RenderScene& scene, SampleStream& samples, PrimaryHitRecord& primary) const {
    Contributions contributions(path.result, settings_.clamp);
    const int depth = path.depth;
    path.casts_shadow = false;
    if (!found) {
        for (const LightChoice& light : scene.infinite_lights()) {
            const Rgb emitted = light.light->escaped_radiance(ray.direction);
            if (emitted.is_black()) continue;
            const float weight =
                path.previous_was_delta
                    ? 1.0f
                    : power_heuristic(path.previous_pdf,
                                      light.probability *
                                          light.light->pdf(path.previous_point, ray.direction,
                                                           std::numeric_limits<float>::infinity(), {}));
            contributions.add(path.throughput * emitted * weight);
        }
        return false;
    }
    const SurfaceHit& hit = *found;
    const Vec3f towards_viewer = -ray.direction;
    if (depth == 0) primary.record(hit);

    const Rgb emitted = hit.material->emission(hit, towards_viewer);
    if (!emitted.is_black()) {
        float weight = 1;
        const LightChoice& area_light = hit.object->area_light;
        if (!path.previous_was_delta && area_light.light) {
            const float light_pdf =
                area_light.probability *
                area_light.light->pdf(path.previous_point, ray.direction, hit.t, hit.geometric_normal);
            weight = power_heuristic(path.previous_pdf, light_pdf);
        }
        contributions.add(path.throughput * emitted * weight);
    }
    if (depth >= settings_.max_depth) return false;
    const SurfaceBsdf bsdf = hit.material->bsdf(hit);
    if (!bsdf.scatters()) return false;

    const ShadingFrame frame(hit.shading_normal, hit.tangent);
    const Vec3f wo = frame.to_local(towards_viewer);

    // Two bounces own four Sobol' blocks, in this order, used or not: the first bounce's light block (a point
    // on the light, the choice among lights, the BSDF's lobe choice), both bounces' directions as one 4-D
    // point, both bounces' Russian roulette, the second bounce's light block. Consecutive directions are so
    // stratified jointly, not only each on its own (docs/decisions.md). A block is computed only when
    // something reads it (a delta light and a single-lobe BSDF read no light block; roulette may be off); its
    // dimensions are skipped either way, so every value keeps its dimension.
    const bool first_of_pair = depth % 2 == 0;
    Sampler::Block light{};
    if (!scene.light_sampling_is_deterministic() || bsdf.chooses_lobe())
        light = samples.next_block();
    else
        samples.skip_block();
    if (first_of_pair) {
        path.pair_directions = samples.next_block();
        path.pair_roulette = {};
        if (depth + 2 >= settings_.russian_roulette_depth)
            path.pair_roulette = samples.next_block();
        else
            samples.skip_block();
    }
    const std::array<float, 2> u_light_point = {light[0], light[1]};
    const float u_light = light[2];
    const float u_lobe = light[3];
    const std::array<float, 2> u_direction =
        first_of_pair ? std::array<float, 2>{path.pair_directions[0], path.pair_directions[1]}
                      : std::array<float, 2>{path.pair_directions[2], path.pair_directions[3]};
    const float u_roulette = path.pair_roulette[std::size_t(depth % 2)];

    // Next-event estimation: one light, chosen in proportion to power. The shadow ray is traced by the caller,
    // with those of the other paths traced together.
    if (!bsdf.is_fully_delta()) {
        const LightChoice choice = scene.choose_light(u_light);
        if (choice.light) {
            const LightSample light = choice.light->sample(hit.position, u_light_point);
            const Vec3f wi = frame.to_local(light.direction);
            if (light.pdf > 0 && !light.radiance.is_black()) {
                // What the light would add is a multiple of the throughput times f: when that is black in
                // every channel (a red wall seen along a green path), the shadow ray cannot change the result.
                const Rgb throughput_f = path.throughput * (bsdf.eval(wo, wi) * std::abs(wi.z));
                if (!throughput_f.is_black() && sides_agree(light.direction, hit.geometric_normal, wi.z)) {
                    const float light_pdf = choice.probability * light.pdf;
                    const float weight = light.is_delta ? 1.0f : power_heuristic(light_pdf, bsdf.pdf(wo, wi));
                    path.casts_shadow = true;
                    shadow = shadow_ray(hit, light);
                    path.unblocked = throughput_f * light.radiance * (weight / light_pdf);
                }
            }
        }
    }

    // The next ray would only look for emission: with nothing a ray can hit emitting (delta lights only),
    // the path ends here with the same result and without that ray.
    if (depth + 1 >= settings_.max_depth && !scene.emission_can_be_hit()) return false;

    // Continue the path by sampling the BSDF.
    const std::optional<BsdfSample> scattered = bsdf.sample(wo, u_lobe, u_direction);
    if (!scattered || scattered->pdf <= 0 || scattered->weight.is_black()) return false;
    // Unit within a few roundings (a unit wi in an orthonormal frame): normalising again would put a square root
    // and a division on the way to the next ray for nothing.
    const Vec3f direction = frame.to_world(scattered->wi);
    if (!sides_agree(direction, hit.geometric_normal, scattered->wi.z)) return false;
    path.throughput *= scattered->weight;
    // Every later contribution is a multiple of the throughput: a black one ends the path with the same result
    // (a green path after a red bounce), so its remaining rays are not traced.
    if (path.throughput.is_black()) return false;
    if (scattered->is_transmission) path.eta_scale *= scattered->eta * scattered->eta;
    path.previous_was_delta = scattered->is_delta;
    path.previous_pdf = scattered->pdf;
    path.previous_point = hit.position;
    ray = Ray{hit.spawn_origin(direction), direction, 0, std::numeric_limits<float>::infinity(), hit.footprint,
              scattered_cone_spread(ray.cone_spread, *scattered)};
    path.depth = depth + 1;

    if (depth + 1 >= settings_.russian_roulette_depth) {
        const float survival = std::min(1.0f, path.throughput.max() * path.eta_scale);
        if (!(u_roulette < survival)) return false;
        path.throughput *= 1.0f / survival;
    }
    return true;
}

void PathIntegrator::add_unblocked(Path& path) const {
    Contributions(path.result, settings_.clamp).add(path.unblocked);
}

Rgb PathIntegrator::radiance(const Ray& camera_ray, const RenderScene& scene, SampleStream& samples,
                             PrimaryHitRecord& primary) const {
    Ray ray = camera_ray, shadow;
    Path path(ray);
    for (bool continues = true; continues;) {
        const RayKind kind = path.depth == 0 ? RayKind::Camera : RayKind::Secondary;
        continues = bounce(path, ray, shadow, scene.intersect(ray, kind), scene, samples, primary);
        if (path.casts_shadow && !scene.occluded(shadow)) add_unblocked(path);
    }
    return path.result;
}

std::size_t PathIntegrator::samples_traced_together(const RenderScene&) const {
    static_assert(kLanes <= kMaxSamplesTogether && kMaxSamplesTogether <= SampleStream::kMaxStreamsTogether);
    return kMaxSamplesTogether;
}

std::string PathIntegrator::packet_description(const RenderScene&) const {
    return std::to_string(kMaxSamplesTogether) + " samples (a pixel's, or several pixels') as paths in step, " +
           "their rays " + std::to_string(kLanes) + "-ray packet queries kept full as paths end";
}

// The paths of a group's samples (a pixel's, then the next pixel's) advance in step, one bounce each per round (their
// depths stay equal), so that each round's rays are packet queries and their shadow rays others: Embree traverses
// its tree once for a packet, which costs less than once per ray when the rays are alike, as a pixel's camera rays
// are. Paths that end leave the group and the live ones close up, so that the packets stay full as paths end
// (escaping paths would otherwise leave most lanes of the later rounds empty). Each path does what radiance() does,
// in the same order, so its result does not depend on its companions.
void PathIntegrator::radiance_of_samples(std::span<const Ray> camera_rays, const RenderScene& scene,
                                         std::span<SampleStream> samples, std::span<PrimaryHitRecord> primary,
                                         std::span<Rgb> radiance) const {
    constexpr std::size_t kMost = kMaxSamplesTogether;
    const std::size_t count = camera_rays.size();
    std::array<std::optional<Path>, kMost> paths;
    std::array<Ray, kMost> rays, shadows;
    std::array<std::optional<SurfaceHit>, kMost> hits;
    std::array<std::size_t, kMost> sample_of, casting;  // a slot's sample; the slots whose bounce cast a shadow ray
    std::array<bool, kMost> continuing;
    for (std::size_t slot = 0; slot < count; ++slot) {
        rays[slot] = camera_rays[slot];
        paths[slot].emplace(rays[slot]);
        sample_of[slot] = slot;
    }
    const auto first_lanes = [](std::size_t n) { return (1u << n) - 1u; };  // n ≤ kLanes
    for (std::size_t live = count, depth = 0; live > 0; ++depth) {
        const RayKind kind = depth == 0 ? RayKind::Camera : RayKind::Secondary;
        for (std::size_t first = 0; first < live; first += kLanes) {
            const std::size_t n = std::min<std::size_t>(kLanes, live - first);
            scene.intersect(std::span(rays.data() + first, n), first_lanes(n), kind, std::span(hits.data() + first, n));
        }
        std::size_t casts = 0;
        for (std::size_t slot = 0; slot < live; ++slot) {
            Path& path = *paths[slot];
            // The shadow rays side by side, in slot order: each bounce writes its own after those before it.
            continuing[slot] = bounce(path, rays[slot], shadows[casts], hits[slot], scene, samples[sample_of[slot]],
                                      primary[sample_of[slot]]);
            if (path.casts_shadow) casting[casts++] = slot;
        }
        for (std::size_t first = 0; first < casts; first += kLanes) {
            const std::size_t n = std::min<std::size_t>(kLanes, casts - first);
            const unsigned blocked = scene.occluded(std::span(shadows.data() + first, n), first_lanes(n));
            const unsigned reached = first_lanes(n) & ~blocked;
            for (unsigned lanes = reached; lanes; lanes &= lanes - 1)
                add_unblocked(*paths[casting[first + std::size_t(std::countr_zero(lanes))]]);
        }
        std::size_t kept = 0;
        for (std::size_t slot = 0; slot < live; ++slot) {
            if (!continuing[slot]) {
                radiance[sample_of[slot]] = paths[slot]->result;
                continue;
            }
            if (kept != slot) {
                paths[kept] = std::move(paths[slot]);
                rays[kept] = rays[slot];
                sample_of[kept] = sample_of[slot];
            }
            ++kept;
        }
        live = kept;
    }
}

std::map<std::string, std::string> PathIntegrator::settings() const {
    return {{"max_depth", std::to_string(settings_.max_depth)},
            {"russian_roulette_depth", std::to_string(settings_.russian_roulette_depth)},
            {"clamp", settings_.clamp > 0 ? std::to_string(settings_.clamp) : "off"}};
}

namespace {

PathSettings parse_settings(const SceneNode& node) {
    PathSettings settings;
    settings.max_depth = node.integer_or("max_depth", settings.max_depth, NumberRange::between(1, 1024));
    settings.russian_roulette_depth =
        node.integer_or("russian_roulette_depth", settings.russian_roulette_depth, NumberRange::between(1, 1024));
    settings.clamp = float(node.number_or("clamp", 0.0, NumberRange::non_negative()));
    return settings;
}

}  // namespace

ISOTRACE_REGISTER_PLUGIN(integrator_registry, "path",
                         "path tracing with NEE + MIS; max_depth (16), russian_roulette_depth (4), clamp (0 = off)",
                         [](const SceneNode& node) -> std::unique_ptr<Integrator> {
                             return std::make_unique<PathIntegrator>(parse_settings(node));
                         })

ISOTRACE_REGISTER_PLUGIN(integrator_registry, "direct",
                         "direct lighting only (emission + one bounce of NEE and BSDF sampling with MIS); clamp",
                         [](const SceneNode& node) -> std::unique_ptr<Integrator> {
                             PathSettings settings;
                             settings.max_depth = 1;
                             settings.russian_roulette_depth = 1024;
                             settings.clamp = float(node.number_or("clamp", 0.0, NumberRange::non_negative()));
                             return std::make_unique<PathIntegrator>(settings);
                         })

}  // namespace isotrace
