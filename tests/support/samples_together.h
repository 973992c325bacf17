#pragma once
// The check that tracing a pixel's samples together changes no sample: for tests of the path tracer's packets.
#include <array>
#include <cstdint>
#include <functional>
#include <span>

#include "renderer/plugin/integrator.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace::testing {

// Traces a group of one pixel's consecutive samples: radiance[i] and primary[i] for camera_rays[i] with samples[i].
using TraceGroup = std::function<void(std::span<const Ray> camera_rays, std::span<SampleStream> samples,
                                      std::span<PrimaryHitRecord> primary, std::span<Rgb> radiance)>;

// For every pixel of `pixels` ({x, y}), samples [0, count) traced in groups of eight (the last one shorter) by
// `trace` and one at a time by the scene's integrator's radiance(): fails (gtest) on any differing bit of the
// radiance, on a differing primary-hit record or on a different number of sampler dimensions taken; returns how
// many samples carried light.
int expect_groups_match_single_paths(const LoadedScene& loaded, std::span<const std::array<int, 2>> pixels,
                                     std::uint32_t count, const TraceGroup& trace);

}  // namespace isotrace::testing
