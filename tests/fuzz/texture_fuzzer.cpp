// Image textures (PNG by default; the first byte picks the extension OIIO uses to choose a reader): any input
// loads or throws InputError, and the memory estimate from the header keeps claims of huge sizes harmless.
#include <cstdint>

#include "renderer/colour/colour_system.h"
#include "renderer/core/input_error.h"
#include "renderer/core/memory_budget.h"
#include "renderer/image/image_codec.h"
#include "renderer/textures/image_texture.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const isotrace::ColourSystem colours("", "ACEScg");
    static const char* const kExtensions[] = {".png", ".exr", ".jpg", ".tif", ".hdr"};
    if (size == 0) return 0;
    // The image module's libraries are loaded once, before the first input: they are the process's memory, and the
    // first image read under a budget charges them (over 100 MB), which would refuse every image under 16 MB.
    static const bool image_module_loaded = (isotrace::image_codec(), true);
    (void)image_module_loaded;
    const char* extension = kExtensions[data[0] % 5];
    // 16 MB (a 1024x1024 RGBA float image): the budget also bounds the work per input, and OpenImageIO reading a
    // mutated header's 256 MB of scanlines took over 30 s under ASan (its allocator poisons every freed buffer).
    isotrace::MemoryBudget budget(std::uint64_t(16) << 20);
    try {
        isotrace::ImageTexture::load(isotrace::fuzz::write_input(data + 1, size - 1, extension), "", colours, budget);
    } catch (const isotrace::InputError&) {
    }
    return 0;
}
