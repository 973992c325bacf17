// JSON reader and scene loader: any input must load or throw InputError (exit 2), never crash, hang or throw
// anything else (which the CLI reports as an internal failure, exit 1).
#include <cstdint>

#include "renderer/core/input_error.h"
#include "renderer/scene/loaded_scene.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    isotrace::SceneOverrides overrides;
    overrides.max_memory_bytes = std::uint64_t(512) << 20;  // the fuzzer's own limit is 2 GB
    try {
        isotrace::load_scene(isotrace::fuzz::write_input(data, size, ".json"), overrides);
    } catch (const isotrace::InputError&) {
    }
    return 0;
}
