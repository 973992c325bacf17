#include "renderer/image_compare/image_file.h"

#include <OpenImageIO/imageio.h>

#include <limits>

#include "renderer/core/input_error.h"

namespace isotrace {

ImageFile read_image_file(const std::string& path) {
    const auto fail = [&](const std::string& why) { return InputError({path, 0, 0}, "", why); };
    auto input = OIIO::ImageInput::open(path);
    if (!input) {
        std::string why = OIIO::geterror();
        throw fail("cannot read the image: " + (why.empty() ? std::string("unknown format") : why));
    }
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1 || spec.depth != 1)
        throw fail("not a 2-D image with at least one channel");
    const std::size_t count = std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels);
    if (count > std::size_t(std::numeric_limits<int>::max())) throw fail("the image is too large to compare");
    ImageFile image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.channelnames;
    image.pixels.resize(count);
    const OIIO::TypeDesc::BASETYPE base = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
    image.display_referred =
        !(base == OIIO::TypeDesc::FLOAT || base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::DOUBLE);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw fail("cannot read the pixels: " + input->geterror());
    for (const OIIO::ParamValue& attribute : spec.extra_attribs)
        image.metadata.emplace_back(attribute.name().string(), attribute.get_string());
    std::array<float, 8> xy{};
    if (spec.getattribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), xy.data())) image.chromaticities = xy;
    return image;
}

}  // namespace isotrace
