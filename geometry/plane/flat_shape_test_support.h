#pragma once
// Test helpers of the flat shapes' scene-format tests: a one-object scene around a shape's JSON, and the check that
// each bad shape fails to load with the expected words in its message.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "geometry/mesh/mesh_test_support.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace::flat_test {

// A scene of one object of material "m" whose shape is `shape`; `object_keys` ("\"transform\": {...}, ") adds keys
// to the object.
inline std::string scene_with(const std::string& shape, const std::string& object_keys = "") {
    return R"({"isotrace": 1, "film": {"resolution": [4, 4]},
  "camera": {"type": "perspective", "look_at": {"eye": [0, 0, 5], "target": [0, 0, 0]}},
  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"material": "m", )" + object_keys + R"("shape": )" + shape + "}]}";
}

struct BadShape {
    const char* shape;
    const char* message;  // a part of the error message
};

inline void expect_errors(mesh_test::ScratchDirectory& dir, std::initializer_list<BadShape> cases) {
    for (const auto& [shape, expected] : cases) {
        const std::string path = dir.write("bad.json", scene_with(shape));
        const std::string message = mesh_test::input_error_message([&] { load_scene(path); });
        EXPECT_NE(message.find(expected), std::string::npos) << message;
    }
}

}  // namespace isotrace::flat_test
