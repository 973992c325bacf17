#include "tests/support/samples_together.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <string>
#include <vector>

#include "renderer/render/sample_camera_ray.h"

namespace isotrace::testing {

int expect_groups_match_single_paths(const LoadedScene& loaded, std::span<const std::array<int, 2>> pixels,
                                     std::uint32_t count, std::size_t group, const TraceGroup& trace) {
    const auto bits = [](float v) { return std::bit_cast<std::uint32_t>(v); };
    struct Key {
        int x, y;
        std::uint32_t index;
    };
    std::vector<Key> keys;  // each pixel's samples in order, the pixels in turn
    for (const std::array<int, 2>& pixel : pixels)
        for (std::uint32_t index = 0; index < count; ++index) keys.push_back({pixel[0], pixel[1], index});
    const auto stream_of = [&](const Key& key) {
        return SampleStream(*loaded.sampler, {std::uint32_t(key.x), std::uint32_t(key.y), key.index});
    };
    const auto camera_ray = [&](const Key& key, SampleStream& stream) {
        return sample_camera_ray(loaded, key.x, key.y, stream).ray;
    };
    int lit = 0;
    for (std::size_t first = 0; first < keys.size(); first += group) {
        const std::size_t size = std::min(group, keys.size() - first);
        std::vector<SampleStream> streams(size);
        std::vector<Ray> rays(size);
        std::vector<PrimaryHitRecord> primary(size);
        std::vector<Rgb> radiance(size);
        for (std::size_t i = 0; i < size; ++i) {
            streams[i] = stream_of(keys[first + i]);
            rays[i] = camera_ray(keys[first + i], streams[i]);
        }
        trace(rays, streams, primary, radiance);
        for (std::size_t i = 0; i < size; ++i) {
            const Key& key = keys[first + i];
            SampleStream single = stream_of(key);
            const Ray ray = camera_ray(key, single);
            PrimaryHitRecord record;
            const Rgb expected = loaded.integrator->radiance(ray, *loaded.scene, single, record);
            SCOPED_TRACE("pixel " + std::to_string(key.x) + ", " + std::to_string(key.y) + ", sample " +
                         std::to_string(key.index));
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
    return lit;
}

}  // namespace isotrace::testing
