#pragma once
// A camera sample's ray: the offset in its pixel drawn from the filter first, then the lens' point. Every render
// takes a sample's first dimensions in this order, so a sample's ray is the same however samples are grouped.
#include "renderer/plugin/camera.h"
#include "renderer/plugin/pixel_filter.h"
#include "renderer/sampling/sampler.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace {

struct SampleCameraRay {
    Ray ray;
    FilterSample offset;
};

inline SampleCameraRay sample_camera_ray(const LoadedScene& loaded, int x, int y, SampleStream& stream) {
    const FilterSample offset = loaded.filter->sample(stream.next_2d());
    return {loaded.camera->generate_ray(float(x) + 0.5f + offset.dx, float(y) + 0.5f + offset.dy, stream.next_2d()),
            offset};
}

}  // namespace isotrace
