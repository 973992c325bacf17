#include "integrators/preview/preview_integrator.h"

#include <numbers>

#include "renderer/params/emitted_colour.h"
#include "renderer/plugin/shadow_ray.h"
#include "renderer/sampling/sampler.h"
#include "renderer/sampling/warps.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {

Rgb PreviewIntegrator::radiance(const Ray& camera_ray, const RenderScene& scene, SampleStream& samples,
                                PrimaryHitRecord& primary) const {
    const std::optional<SurfaceHit> found = scene.intersect(camera_ray, RayKind::Camera);
    if (!found) return settings_.background;
    SurfaceHit hit = *found;
    const Rgb emitted = hit.material->emission(hit, -normalize(camera_ray.direction));
    // Two-sided shading: turn the normals towards the viewer.
    if (dot(hit.geometric_normal, camera_ray.direction) > 0) {
        hit.geometric_normal = -hit.geometric_normal;
        hit.shading_normal = -hit.shading_normal;
    }
    const Rgb albedo = hit.material->albedo(hit);
    primary.record(hit, albedo);

    Rgb result = emitted;
    if (albedo.is_black()) return result;

    Rgb direct;
    for (const auto& light : scene.lights()) {
        const LightSample s = light->sample(hit.position, samples.next_2d());
        const float cosine = dot(hit.shading_normal, s.direction);
        if (cosine <= 0 || s.pdf <= 0 || s.radiance.is_black()) continue;
        if (!scene.occluded(shadow_ray(hit, s))) direct += s.radiance * (cosine / s.pdf);
    }
    result += albedo * direct * float(std::numbers::inv_pi);

    if (!settings_.ambient.is_black()) {
        Vec3f tangent, bitangent;
        orthonormal_basis(hit.shading_normal, tangent, bitangent);
        int unoccluded = 0;
        for (int i = 0; i < settings_.ambient_samples; ++i) {
            const Vec3f local = square_to_cosine_hemisphere(samples.next_2d());
            const Vec3f direction = tangent * local.x + bitangent * local.y + hit.shading_normal * local.z;
            if (dot(direction, hit.geometric_normal) <= 0) continue;  // below the true surface: blocked
            Ray probe{hit.spawn_origin(direction), direction, 0, settings_.ambient_distance};
            if (!scene.occluded(probe)) ++unoccluded;
        }
        result += albedo * settings_.ambient * (float(unoccluded) / float(settings_.ambient_samples));
    }
    return result;
}

namespace {

bool emits(const SceneObject& object) {
    if (object.material && object.material->is_emissive()) return true;
    for (const Material* part : object.part_materials)
        if (part && part->is_emissive()) return true;
    return false;
}

}  // namespace

std::vector<std::string> PreviewIntegrator::light_left_out(const RenderScene& scene) const {
    std::vector<std::string> left_out;
    if (!scene.infinite_lights().empty())
        left_out.push_back("the environment as seen by rays that leave the scene (they show the uniform background; "
                           "only the environment's direct light is kept)");
    std::size_t unlit_by = 0, area_lights = 0;
    for (std::uint32_t id = 0; id < scene.object_count(); ++id) {
        const SceneObject object = scene.object(id);
        if (emits(object) && !object.area_light.light) ++unlit_by;
        if (object.area_light.light) ++area_lights;
    }
    // Their direct light is kept; what a user misses is what makes area lights worth using.
    if (area_lights > 0)
        left_out.push_back("the reflections and the bounced light of " + std::to_string(area_lights) +
                           " area light(s) (every surface is shaded as diffuse, lit directly)");
    if (unlit_by > 0)
        left_out.push_back("the light that " + std::to_string(unlit_by) +
                           " emissive object(s) cast on other surfaces (they cannot be sampled as lights)");
    return left_out;
}

ISOTRACE_REGISTER_PLUGIN(integrator_registry, "preview",
                         "direct light from every light, no bounces, + ambient occlusion under a uniform sky; "
                         "ambient, background, ambient_samples, ambient_distance",
                         [](const SceneNode& node) -> std::unique_ptr<Integrator> {
                             PreviewSettings settings;
                             settings.ambient = emitted_colour(node, "ambient", settings.ambient);
                             settings.background = emitted_colour(node, "background", settings.ambient);
                             settings.ambient_samples =
                                 node.integer_or("ambient_samples", 1, NumberRange::between(1, 1024));
                             settings.ambient_distance =
                                 float(node.number_or("ambient_distance", 1e30, NumberRange::positive()));
                             return std::make_unique<PreviewIntegrator>(settings);
                         })

}  // namespace isotrace
