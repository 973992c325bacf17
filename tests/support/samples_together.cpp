#include "tests/support/samples_together.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <string>
#include <vector>

#include "renderer/plugin/camera.h"
#include "renderer/plugin/pixel_filter.h"

namespace isotrace::testing {

int expect_groups_match_single_paths(const LoadedScene& loaded, std::span<const std::array<int, 2>> pixels,
                                     std::uint32_t count, const TraceGroup& trace) {
    const auto bits = [](float v) { return std::bit_cast<std::uint32_t>(v); };
    int lit = 0;
    for (const std::array<int, 2>& pixel : pixels) {
        const int x = pixel[0], y = pixel[1];  // not a structured binding: the lambda below captures them
        const auto camera_ray = [&](SampleStream& stream) {
            const FilterSample offset = loaded.filter->sample(stream.next_2d());
            return loaded.camera->generate_ray(float(x) + 0.5f + offset.dx, float(y) + 0.5f + offset.dy,
                                               stream.next_2d());
        };
        for (std::uint32_t first = 0; first < count; first += 8) {
            const std::size_t group = std::min<std::size_t>(8, count - first);
            std::vector<SampleStream> streams(group);
            std::vector<Ray> rays(group);
            std::vector<PrimaryHitRecord> primary(group);
            std::vector<Rgb> radiance(group);
            for (std::size_t i = 0; i < group; ++i) {
                streams[i] = SampleStream(*loaded.sampler, {std::uint32_t(x), std::uint32_t(y), first + std::uint32_t(i)});
                rays[i] = camera_ray(streams[i]);
            }
            trace(rays, streams, primary, radiance);
            for (std::size_t i = 0; i < group; ++i) {
                SampleStream single(*loaded.sampler, {std::uint32_t(x), std::uint32_t(y), first + std::uint32_t(i)});
                const Ray ray = camera_ray(single);
                PrimaryHitRecord record;
                const Rgb expected = loaded.integrator->radiance(ray, *loaded.scene, single, record);
                SCOPED_TRACE("pixel " + std::to_string(x) + ", " + std::to_string(y) + ", sample " +
                             std::to_string(first + i));
                EXPECT_EQ(bits(radiance[i].r), bits(expected.r));
                EXPECT_EQ(bits(radiance[i].g), bits(expected.g));
                EXPECT_EQ(bits(radiance[i].b), bits(expected.b));
                EXPECT_EQ(primary[i].hit, record.hit);
                EXPECT_EQ(primary[i].albedo, record.albedo);
                EXPECT_EQ(primary[i].shading_normal, record.shading_normal);
                EXPECT_EQ(primary[i].position, record.position);
                EXPECT_EQ(primary[i].object_id, record.object_id);
                EXPECT_EQ(primary[i].primitive_id, record.primitive_id);
                EXPECT_EQ(streams[i].dimension(), single.dimension());  // the same blocks taken
                if (!expected.is_black()) ++lit;
            }
        }
    }
    return lit;
}

}  // namespace isotrace::testing
