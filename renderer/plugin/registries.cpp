// The one definition of each plugin registry (function-local statics: safe to use from other static
// initialisers, which is how plugins register themselves).
#include "renderer/plugin/camera.h"
#include "renderer/plugin/integrator.h"
#include "renderer/plugin/light.h"
#include "renderer/plugin/material.h"
#include "renderer/plugin/pixel_filter.h"
#include "renderer/plugin/sampler_registry.h"
#include "renderer/plugin/shape.h"

namespace isotrace {

Registry<Shape>& shape_registry() {
    static Registry<Shape> registry("shape");
    return registry;
}

Registry<Shape, std::unique_ptr<Shape>>& shape_wrapper_registry() {
    static Registry<Shape, std::unique_ptr<Shape>> registry("shape wrapper");
    return registry;
}

Registry<Material>& material_registry() {
    static Registry<Material> registry("material");
    return registry;
}

Registry<Light>& light_registry() {
    static Registry<Light> registry("light");
    return registry;
}

Registry<Camera, const RasterSize&>& camera_registry() {
    static Registry<Camera, const RasterSize&> registry("camera");
    return registry;
}

Registry<PixelFilter>& pixel_filter_registry() {
    static Registry<PixelFilter> registry("pixel filter");
    return registry;
}

Registry<Integrator>& integrator_registry() {
    static Registry<Integrator> registry("integrator");
    return registry;
}

Registry<Sampler, std::uint64_t>& sampler_registry() {
    static Registry<Sampler, std::uint64_t> registry("sampler");
    return registry;
}

}  // namespace isotrace
