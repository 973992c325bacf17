#pragma once
// Warnings about a render whose image may not be what its scene describes: light the integrator leaves out, and a
// beauty that is black everywhere or has pixels that are not finite. Printed by the CLI; the library only reports.
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/film/film.h"
#include "renderer/scene/loaded_scene.h"

namespace isotrace::cli {

// What the beauty channels (R, G, B) of a resolved image hold.
struct BeautyCheck {
    std::uint64_t pixels = 0;
    std::uint64_t non_finite_pixels = 0;  // a channel is NaN or infinite
    bool all_black = true;                // every finite pixel is 0 in R, G and B
};

BeautyCheck check_beauty(const ImageBuffer& image);

// Warnings, each one line without the "isotrace: warning: " prefix. The integrator's is one line naming all it
// leaves out, empty when it leaves out nothing.
std::string light_left_out_warning(const LoadedScene& scene);
std::vector<std::string> beauty_warnings(const BeautyCheck& check);

}  // namespace isotrace::cli
