// The "blobs" scene type's memory estimate: generated elements are charged to the memory budget before they are
// allocated, so a huge "generate.count" is refused with the figure (exit 2) instead of ending in std::bad_alloc.
#include <gtest/gtest.h>

#include <string>

#include "geometry/implicit/blob_group.h"
#include "geometry/mesh/mesh_test_support.h"
#include "renderer/core/memory_budget.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace {
namespace {

using mesh_test::input_error_message;
using mesh_test::ScratchDirectory;

std::string scene_generating(long long count) {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"plain": {"type": "diffuse"}},
  "objects": [{"material": "plain", "shape": {"type": "blobs",
    "generate": {"count": )" +
           std::to_string(count) + R"(, "min": [-1, -1, -1], "max": [1, 1, 1], "radius": [0.05, 0.1]}}}]})";
}

SceneOverrides with_memory_limit(std::uint64_t bytes) {
    SceneOverrides overrides;
    overrides.max_memory_bytes = bytes;
    return overrides;
}

TEST(BlobsPlugin, TheDocumentedMaximumCountIsRefusedWithTheEstimateBeforeAllocating) {
    ScratchDirectory directory;
    const std::string path = directory.write("scene.json", scene_generating(100'000'000));
    const std::string message =
        input_error_message([&] { load_scene(path, with_memory_limit(std::uint64_t(8) << 30)); });
    EXPECT_NE(message.find("objects[0].shape.generate.count"), std::string::npos) << message;
    EXPECT_NE(message.find("100000000 generated elements needs about " +
                           format_bytes(100'000'000 * BlobGroup::kPeakBytesPerElement)),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("limit of 8.59 GB"), std::string::npos) << message;
}

TEST(BlobsPlugin, GeneratedElementsAreChargedAtTheirMeasuredSize) {
    ScratchDirectory directory;
    constexpr int kCount = 2000;
    const std::string path = directory.write("scene.json", scene_generating(kCount));
    const std::uint64_t elements = kCount * BlobGroup::kPeakBytesPerElement;
    // The film (4x4 pixels) is charged as well, so exactly the elements' estimate is too little ...
    const std::string message = input_error_message([&] { load_scene(path, with_memory_limit(elements)); });
    EXPECT_NE(message.find("generate.count"), std::string::npos) << message;
    // ... and a megabyte more is enough.
    const auto loaded = load_scene(path, with_memory_limit(elements + (1 << 20)));
    EXPECT_EQ(loaded->scene->build_statistics().primitives_by_type.count("blobs"), 1u);
}

}  // namespace
}  // namespace isotrace
