#include "tools/cli/diff_z_test_input.h"

#include <charconv>
#include <limits>
#include <variant>

#include "renderer/core/input_error.h"
#include "renderer/image_compare/image_channels.h"

namespace isotrace::cli {
namespace {

// An integer attribute in EXR, text in PNG/JPEG/TIFF.
std::optional<int> spp_metadata(const ImageFile& file) {
    const ImageMetadata::Value* value = file.metadata.find("isotrace:spp");
    if (!value) return std::nullopt;
    if (const auto* integer = std::get_if<std::int64_t>(value))
        return *integer >= 1 && *integer <= std::numeric_limits<int>::max() ? std::optional<int>(int(*integer))
                                                                              : std::nullopt;
    const auto* text = std::get_if<std::string>(value);
    if (!text) return std::nullopt;
    int spp = 0;
    const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), spp);
    if (error == std::errc() && end == text->data() + text->size() && spp >= 1) return spp;
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
    // The same seed makes the test's samples a prefix of the reference's: the two means are then not independent.
    const ImageMetadata::Value* reference_seed = reference.metadata.find("isotrace:seed");
    const ImageMetadata::Value* test_seed = test.metadata.find("isotrace:seed");
    if (reference_seed && test_seed && *reference_seed == *test_seed)
        throw InputError({test_path, 0, 0}, "",
                         "rendered with the same seed as the reference (isotrace:seed): the z-test needs independent "
                         "samples; render the test with another --seed");
    ZTestInput input;
    input.reference_mean = colour_of(reference, reference_path);
    input.reference_variance = channels_as_rgb(reference, {"variance.R", "variance.G", "variance.B"}, reference_path);
    input.reference_samples = channel_plane(reference, "sampleCount", reference_path);
    input.test = colour_of(test, test_path);
    if (find_channel(test, "variance.R"))
        input.test_variance = channels_as_rgb(test, {"variance.R", "variance.G", "variance.B"}, test_path);
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
