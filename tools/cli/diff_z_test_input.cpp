#include "tools/cli/diff_z_test_input.h"

#include <charconv>

#include "renderer/core/input_error.h"
#include "renderer/image_compare/image_channels.h"

namespace isotrace::cli {
namespace {

std::optional<int> spp_metadata(const ImageFile& file) {
    for (const auto& [name, value] : file.metadata) {
        if (name != "isotrace:spp") continue;
        int spp = 0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), spp);
        if (error == std::errc() && end == value.data() + value.size() && spp >= 1) return spp;
    }
    return std::nullopt;
}

}  // namespace

ZTestInput z_test_input(const ImageFile& reference, const std::string& reference_path, const ImageFile& test,
                        const std::string& test_path, std::optional<int> test_spp) {
    for (const char* needed : {"variance.R", "variance.G", "variance.B", "sampleCount"})
        if (!find_channel(reference, needed))
            throw InputError({reference_path, 0, 0}, "",
                             std::string("the z-test reference needs a \"") + needed +
                                 "\" channel: render it with --aov variance,sample_count (and many samples)");
    ZTestInput input;
    input.reference_mean = colour_of(reference, reference_path);
    input.reference_variance = channels_as_rgb(reference, {"variance.R", "variance.G", "variance.B"}, reference_path);
    input.reference_samples = channel_plane(reference, "sampleCount", reference_path);
    input.test = colour_of(test, test_path);
    if (find_channel(test, "sampleCount")) {
        input.test_samples = channel_plane(test, "sampleCount", test_path);
    } else {
        const std::optional<int> spp = test_spp ? test_spp : spp_metadata(test);
        if (!spp)
            throw InputError({test_path, 0, 0}, "",
                             "no sampleCount channel and no isotrace:spp metadata: give its samples per pixel with "
                             "--test-spp N");
        input.test_samples.assign(input.test.pixel_count(), float(*spp));
    }
    return input;
}

}  // namespace isotrace::cli
