#pragma once
// The check that tracing samples together changes no sample: for tests of the path tracer's packets.
#include <array>
#include <cstdint>
#include <functional>
#include <span>

#include "renderer/plugin/integrator.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace::testing {

// Traces a group of samples (a pixel's in order, then the next pixel's): radiance[i] and primary[i] for
// camera_rays[i] with samples[i].
using TraceGroup = std::function<void(std::span<const Ray> camera_rays, std::span<SampleStream> samples,
                                      std::span<PrimaryHitRecord> primary, std::span<Rgb> radiance)>;

// Samples [0, count) of every pixel of `pixels` ({x, y}), taken pixel after pixel, traced in groups of `group`
// (the last one shorter, a group holding the samples of one pixel or of several) by `trace` and one at a time by
// the scene's integrator's radiance(): fails (gtest) on any differing bit of the radiance, on a differing
// primary-hit record or on a different number of sampler dimensions taken; returns how many samples carried light.
int expect_groups_match_single_paths(const LoadedScene& loaded, std::span<const std::array<int, 2>> pixels,
                                     std::uint32_t count, std::size_t group, const TraceGroup& trace);

}  // namespace isotrace::testing
