#include "integrators/path/path_integrator.h"

#include <cmath>
#include <limits>

#include "integrators/path/flat_lambertian_packets.h"
#include "renderer/bsdf/shading_frame.h"
#include "renderer/bsdf/surface_bsdf.h"
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

Rgb PathIntegrator::radiance(const Ray& camera_ray, const RenderScene& scene, SampleStream& samples,
                             PrimaryHitRecord& primary) const {
    Rgb result;
    Contributions contributions(result, settings_.clamp);
    Rgb throughput(1.0f);
    float eta_scale = 1;  // undoes the radiance scaling of refraction for Russian roulette
    Ray ray = camera_ray;
    ray.direction = normalize(ray.direction);  // hit.t is then a distance (needed for light pdfs)
    bool previous_was_delta = true;             // camera rays and delta bounces: no MIS on emitter hits
    float previous_pdf = 0;
    Vec3f previous_point = ray.origin;
    Sampler::Block pair_directions{}, pair_roulette{};  // of the current pair of bounces (below)

    for (int depth = 0;; ++depth) {
        const std::optional<SurfaceHit> found = scene.intersect(ray, depth == 0 ? RayKind::Camera : RayKind::Secondary);
        if (!found) {
            for (const Light* light : scene.infinite_lights()) {
                const Rgb emitted = light->escaped_radiance(ray.direction);
                if (emitted.is_black()) continue;
                const float weight =
                    previous_was_delta
                        ? 1.0f
                        : power_heuristic(previous_pdf, scene.light_probability(light) *
                                                            light->pdf(previous_point, ray.direction,
                                                                       std::numeric_limits<float>::infinity(), {}));
                contributions.add(throughput * emitted * weight);
            }
            break;
        }
        const SurfaceHit& hit = *found;
        const Vec3f towards_viewer = -ray.direction;
        if (depth == 0) primary.record(hit, hit.material->albedo(hit));

        const Rgb emitted = hit.material->emission(hit, towards_viewer);
        if (!emitted.is_black()) {
            float weight = 1;
            const Light* area_light = hit.object->area_light;
            if (!previous_was_delta && area_light) {
                const float light_pdf = scene.light_probability(area_light) *
                                        area_light->pdf(previous_point, ray.direction, hit.t, hit.geometric_normal);
                weight = power_heuristic(previous_pdf, light_pdf);
            }
            contributions.add(throughput * emitted * weight);
        }
        if (depth >= settings_.max_depth) break;
        const SurfaceBsdf bsdf = hit.material->bsdf(hit);
        if (!bsdf.scatters()) break;

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
            pair_directions = samples.next_block();
            pair_roulette = {};
            if (depth + 2 >= settings_.russian_roulette_depth)
                pair_roulette = samples.next_block();
            else
                samples.skip_block();
        }
        const std::array<float, 2> u_light_point = {light[0], light[1]};
        const float u_light = light[2];
        const float u_lobe = light[3];
        const std::array<float, 2> u_direction =
            first_of_pair ? std::array<float, 2>{pair_directions[0], pair_directions[1]}
                          : std::array<float, 2>{pair_directions[2], pair_directions[3]};
        const float u_roulette = pair_roulette[std::size_t(depth % 2)];

        // Next-event estimation: one light, chosen in proportion to power.
        if (!bsdf.is_fully_delta()) {
            const LightChoice choice = scene.choose_light(u_light);
            if (choice.light) {
                const LightSample light = choice.light->sample(hit.position, u_light_point);
                const Vec3f wi = frame.to_local(light.direction);
                if (light.pdf > 0 && !light.radiance.is_black()) {
                    // What the light would add is a multiple of the throughput times f: when that is black in
                    // every channel (a red wall seen along a green path), the shadow ray cannot change the result.
                    const Rgb throughput_f = throughput * (bsdf.eval(wo, wi) * std::abs(wi.z));
                    if (!throughput_f.is_black() && sides_agree(light.direction, hit.geometric_normal, wi.z)) {
                        if (!scene.occluded(shadow_ray(hit, light.direction, light.distance))) {
                            const float light_pdf = choice.probability * light.pdf;
                            const float weight = light.is_delta ? 1.0f : power_heuristic(light_pdf, bsdf.pdf(wo, wi));
                            contributions.add(throughput_f * light.radiance * (weight / light_pdf));
                        }
                    }
                }
            }
        }

        // The next ray would only look for emission: with nothing a ray can hit emitting (delta lights only),
        // the path ends here with the same result and without that ray.
        if (depth + 1 >= settings_.max_depth && !scene.emission_can_be_hit()) break;

        // Continue the path by sampling the BSDF.
        const std::optional<BsdfSample> scattered = bsdf.sample(wo, u_lobe, u_direction);
        if (!scattered || scattered->pdf <= 0 || scattered->weight.is_black()) break;
        const Vec3f direction = normalize(frame.to_world(scattered->wi));
        if (!sides_agree(direction, hit.geometric_normal, scattered->wi.z)) break;
        throughput *= scattered->weight;
        // Every later contribution is a multiple of the throughput: a black one ends the path with the same result
        // (a green path after a red bounce), so its remaining rays are not traced.
        if (throughput.is_black()) break;
        if (scattered->is_transmission) eta_scale *= scattered->eta * scattered->eta;
        previous_was_delta = scattered->is_delta;
        previous_pdf = scattered->pdf;
        previous_point = hit.position;
        ray = Ray{hit.spawn_origin(direction), direction, 0, std::numeric_limits<float>::infinity(), hit.footprint,
                  scattered_cone_spread(ray.cone_spread, *scattered)};

        if (depth + 1 >= settings_.russian_roulette_depth) {
            const float survival = std::min(1.0f, throughput.max() * eta_scale);
            if (!(u_roulette < survival)) break;
            throughput *= 1.0f / survival;
        }
    }
    return result;
}

std::size_t PathIntegrator::samples_traced_together(const RenderScene& scene) const {
    static_assert(kLanes <= kMaxSamplesTogether && kLanes <= SampleStream::kMaxStreamsTogether);
    return scene.flat_lambertian() ? std::size_t(kLanes) : 1;
}

std::string PathIntegrator::packet_description(const RenderScene& scene) const {
    if (!scene.flat_lambertian()) return "";
    return std::to_string(kLanes) + " samples of a pixel in SIMD lanes (flat Lambertian scene), " +
           flat_lambertian_kernel_name() + " kernel";
}

void PathIntegrator::radiance_of_samples(std::span<const Ray> camera_rays, const RenderScene& scene,
                                         std::span<SampleStream> samples, std::span<PrimaryHitRecord> primary,
                                         std::span<Rgb> radiance) const {
    if (const FlatLambertianScene* flat = scene.flat_lambertian())
        flat_lambertian_kernel()(settings_, camera_rays, scene, *flat, samples, primary, radiance);
    else
        Integrator::radiance_of_samples(camera_rays, scene, samples, primary, radiance);
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
