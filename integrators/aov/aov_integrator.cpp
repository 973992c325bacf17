// Debug integrator: shows one property of the first hit as a colour — the shading normal (mapped to
// [0, 1]), the hit distance, the albedo, the uv coordinates, or the object id (a stable pseudo-random colour).
// Misses are black. Usable on its own, for example to check geometry before lighting a scene.
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "renderer/core/enum_names.h"
#include "renderer/plugin/integrator.h"
#include "renderer/plugin/material.h"
#include "renderer/sampling/hash.h"
#include "renderer/scene/render_scene.h"

namespace isotrace {
namespace {

enum class Shown { Normal, Distance, Albedo, Uv, ObjectId };

// The values of "aov", the default first.
constexpr EnumName<Shown> kShownNames[] = {{Shown::Normal, "normal"},
                                           {Shown::Distance, "distance"},
                                           {Shown::Albedo, "albedo"},
                                           {Shown::Uv, "uv"},
                                           {Shown::ObjectId, "object_id"}};

std::string summary() {
    std::string text = std::string("debug view of the first hit; aov: ") + kShownNames[0].name + " (default)";
    for (const auto& entry : std::span(kShownNames).subspan(1)) text += std::string(", ") + entry.name;
    return text;
}

Rgb id_colour(std::uint32_t id) {
    const std::uint64_t h = mix64(id + 1);
    return {0.2f + 0.8f * float(h & 0xFF) / 255.0f, 0.2f + 0.8f * float((h >> 8) & 0xFF) / 255.0f,
            0.2f + 0.8f * float((h >> 16) & 0xFF) / 255.0f};
}

class AovIntegrator final : public Integrator {
public:
    explicit AovIntegrator(Shown shown) : shown_(shown) {}

    Rgb radiance(const Ray& camera_ray, const RenderScene& scene, SampleStream&, PrimaryHitRecord& primary) const override {
        const std::optional<SurfaceHit> hit = scene.intersect(camera_ray, RayKind::Camera);
        if (!hit) return {};
        primary.record(*hit, hit->material ? hit->material->albedo(*hit) : Rgb());
        switch (shown_) {
            case Shown::Normal: {
                const Vec3f n = hit->shading_normal * 0.5f + Vec3f(0.5f, 0.5f, 0.5f);
                return {n.x, n.y, n.z};
            }
            case Shown::Distance: return Rgb(hit->t * length(camera_ray.direction));
            case Shown::Albedo: return primary.albedo;
            case Shown::Uv: return {hit->uv[0], hit->uv[1], 0};
            case Shown::ObjectId: return id_colour(hit->object_index);
        }
        return {};
    }
    std::map<std::string, std::string> settings() const override {
        return {{"aov", enum_name(kShownNames, shown_)}};
    }

private:
    Shown shown_;
};

}  // namespace

ISOTRACE_REGISTER_PLUGIN(integrator_registry, "aov", summary(),
                         [](const SceneNode& node) -> std::unique_ptr<Integrator> {
                             const std::string aov =
                                 node.choice_or("aov", kShownNames[0].name, enum_names(kShownNames));
                             return std::make_unique<AovIntegrator>(enum_value(kShownNames, aov));
                         })

}  // namespace isotrace
