// PLY loader (ASCII and binary): any input loads as a valid mesh or throws InputError.
#include <cstdint>

#include "geometry/mesh/ply_loader.h"
#include "renderer/core/input_error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        isotrace::load_ply(isotrace::fuzz::write_input(data, size, ".ply"));
    } catch (const isotrace::InputError&) {
    }
    return 0;
}
