// The image module (libisotrace_oiio.so): ImageCodec implemented with OpenImageIO, loaded by image_codec() on
// first use so that processes which read and write no image never load OpenImageIO's ~260 libraries. It reads
// every image and writes every format but EXR (the EXR writer module's, renderer/image/openexr/), though it can
// write EXR too: the test of that module compares their bytes.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <stdlib.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "renderer/core/version.h"
#include "renderer/image/image_codec.h"

namespace isotrace {
namespace {

OIIO::TypeDesc oiio_type(PixelType type) {
    switch (type) {
        case PixelType::UInt8: return OIIO::TypeDesc::UINT8;
        case PixelType::Int8: return OIIO::TypeDesc::INT8;
        case PixelType::UInt16: return OIIO::TypeDesc::UINT16;
        case PixelType::Int16: return OIIO::TypeDesc::INT16;
        case PixelType::UInt32: return OIIO::TypeDesc::UINT32;
        case PixelType::Int32: return OIIO::TypeDesc::INT32;
        case PixelType::UInt64: return OIIO::TypeDesc::UINT64;
        case PixelType::Int64: return OIIO::TypeDesc::INT64;
        case PixelType::Half: return OIIO::TypeDesc::HALF;
        case PixelType::Float: return OIIO::TypeDesc::FLOAT;
        case PixelType::Double: return OIIO::TypeDesc::DOUBLE;
        case PixelType::Other: break;
    }
    throw std::logic_error("ImageCodec: no pixel type to encode");
}

PixelType pixel_type(OIIO::TypeDesc type) {
    switch (type.basetype) {
        case OIIO::TypeDesc::UINT8: return PixelType::UInt8;
        case OIIO::TypeDesc::INT8: return PixelType::Int8;
        case OIIO::TypeDesc::UINT16: return PixelType::UInt16;
        case OIIO::TypeDesc::INT16: return PixelType::Int16;
        case OIIO::TypeDesc::UINT32: return PixelType::UInt32;
        case OIIO::TypeDesc::INT32: return PixelType::Int32;
        case OIIO::TypeDesc::UINT64: return PixelType::UInt64;
        case OIIO::TypeDesc::INT64: return PixelType::Int64;
        case OIIO::TypeDesc::HALF: return PixelType::Half;
        case OIIO::TypeDesc::FLOAT: return PixelType::Float;
        case OIIO::TypeDesc::DOUBLE: return PixelType::Double;
        default: return PixelType::Other;
    }
}

void apply_metadata(OIIO::ImageSpec& spec, const ImageMetadata& metadata) {
    for (const auto& [name, value] : metadata.entries) {
        if (const auto* text = std::get_if<std::string>(&value)) spec.attribute(name, *text);
        else if (const auto* real = std::get_if<double>(&value)) spec.attribute(name, float(*real));
        else if (const auto* integer = std::get_if<std::int64_t>(&value)) {
            const std::variant<int, std::string> stored = integer_attribute(*integer);
            if (const int* small = std::get_if<int>(&stored)) spec.attribute(name, *small);
            else spec.attribute(name, std::get<std::string>(stored));
        }
        else {
            const auto& floats = std::get<std::vector<float>>(value);
            spec.attribute(name, OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, int(floats.size())), floats.data());
        }
    }
}

// A scalar integer attribute's value, whatever its width and signedness.
std::int64_t integer_value(const OIIO::ParamValue& attribute) {
    const void* data = attribute.data();
    switch (attribute.type().basetype) {
        case OIIO::TypeDesc::UINT8: return *static_cast<const std::uint8_t*>(data);
        case OIIO::TypeDesc::INT8: return *static_cast<const std::int8_t*>(data);
        case OIIO::TypeDesc::UINT16: return *static_cast<const std::uint16_t*>(data);
        case OIIO::TypeDesc::INT16: return *static_cast<const std::int16_t*>(data);
        case OIIO::TypeDesc::UINT32: return *static_cast<const std::uint32_t*>(data);
        case OIIO::TypeDesc::INT32: return *static_cast<const std::int32_t*>(data);
        case OIIO::TypeDesc::UINT64: return std::int64_t(*static_cast<const std::uint64_t*>(data));
        default: return *static_cast<const std::int64_t*>(data);
    }
}

ImageMetadata metadata_of(const OIIO::ImageSpec& spec) {
    ImageMetadata metadata;
    for (const OIIO::ParamValue& attribute : spec.extra_attribs) {
        const OIIO::TypeDesc type = attribute.type();
        const bool scalar = attribute.nvalues() == 1 && type.aggregate == OIIO::TypeDesc::SCALAR && !type.is_array();
        const std::string name = attribute.name().string();
        if (scalar && type.basetype == OIIO::TypeDesc::STRING)
            metadata.set(name, attribute.get_ustring().string());
        else if (scalar && type.basetype >= OIIO::TypeDesc::UINT8 && type.basetype <= OIIO::TypeDesc::INT64)
            metadata.set(name, integer_value(attribute));
        else if (scalar && type.basetype == OIIO::TypeDesc::DOUBLE)
            metadata.set(name, *static_cast<const double*>(attribute.data()));
        else if (scalar && (type.basetype == OIIO::TypeDesc::FLOAT || type.basetype == OIIO::TypeDesc::HALF))
            metadata.set(name, double(attribute.get_float()));
        else if (type.basetype == OIIO::TypeDesc::FLOAT) {
            const auto* floats = static_cast<const float*>(attribute.data());
            metadata.set(name, std::vector<float>(floats, floats + attribute.datasize() / sizeof(float)));
        }
        else
            metadata.set(name, attribute.get_string(std::numeric_limits<int>::max()));
    }
    return metadata;
}

OIIO::ImageSpec spec_of(const ImageEncoding& image) {
    OIIO::ImageSpec spec(image.width, image.height, int(image.channel_names.size()), oiio_type(image.file_type));
    spec.channelnames = image.channel_names;
    spec.alpha_channel = image.alpha_channel;
    spec.x = image.x;
    spec.y = image.y;
    spec.full_x = 0;
    spec.full_y = 0;
    spec.full_width = image.full_width > 0 ? image.full_width : image.width;
    spec.full_height = image.full_height > 0 ? image.full_height : image.height;
    for (PixelType type : image.channel_file_types) spec.channelformats.push_back(oiio_type(type));
    if (!image.compression.empty()) spec.attribute("compression", image.compression);
    apply_metadata(spec, image.metadata);
    return spec;
}

// Encoded bytes of one image. Writers that take an I/O proxy encode in memory; OIIO 2.4's TIFF writer does not
// work through one (the file loses its size tags), so TIFF goes to a file in a fresh private directory (mode
// 0700: nothing can be planted there) and is read back.
std::vector<unsigned char> encode_with(OIIO::ImageOutput& out, const std::filesystem::path& path,
                                       const OIIO::ImageSpec& spec, OIIO::TypeDesc pixel_type, const void* pixels) {
    const auto fail = [&] { throw std::runtime_error("cannot write " + path.string() + ": " + out.geterror()); };
    if (std::string(out.format_name()) != "tiff") {
        std::vector<unsigned char> bytes;
        OIIO::Filesystem::IOVecOutput memory(bytes);
        OIIO::ImageSpec proxied = spec;
        void* proxy = &memory;
        proxied.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        if (!out.open(path.string(), proxied) || !out.write_image(pixel_type, pixels) || !out.close()) fail();
        return bytes;
    }
    std::string directory = (std::filesystem::temp_directory_path() / "isotrace-encode-XXXXXX").string();
    if (!::mkdtemp(directory.data()))
        throw std::runtime_error("cannot write " + path.string() + ": no private temporary directory: " +
                                 std::strerror(errno));
    const std::filesystem::path file = std::filesystem::path(directory) / ("image" + path.extension().string());
    std::vector<unsigned char> bytes;
    const bool written = out.open(file.string(), spec) && out.write_image(pixel_type, pixels) && out.close();
    if (written) {
        std::ifstream in(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::error_code ignored;
    std::filesystem::remove_all(directory, ignored);
    if (!written) fail();
    return bytes;
}

class OiioImageCodec final : public ImageCodec {
public:
    std::vector<unsigned char> encode(const std::filesystem::path& path, const ImageEncoding& image) const override {
        auto out = OIIO::ImageOutput::create(path.string());
        if (!out) throw std::runtime_error("cannot write " + path.string() + ": " + OIIO::geterror());
        return encode_with(*out, path, spec_of(image), oiio_type(image.memory_type), image.pixels);
    }

    std::string decode(const std::filesystem::path& path, const std::string& format, const BeforePixels& before_pixels,
                       DecodedImage& image) const override {
        // Created for the format and then opened: ImageInput::open would try every other reader on a file its
        // extension's reader refuses.
        auto input = OIIO::ImageInput::create(format);
        if (!input) return "cannot read image: " + OIIO::geterror();
        OIIO::ImageSpec opened;
        if (!input->open(path.string(), opened)) return "cannot read image: " + input->geterror();
        const OIIO::ImageSpec& spec = input->spec();
        if (spec.width < 1 || spec.height < 1 || spec.depth != 1) return "not a 2-D image";
        if (spec.nchannels < 1) return "image has no channels";
        ImageHeader& header = image.header;
        header.format = input->format_name();
        header.width = spec.width;
        header.height = spec.height;
        header.x = spec.x;
        header.y = spec.y;
        header.full_x = spec.full_x;
        header.full_y = spec.full_y;
        header.full_width = spec.full_width;
        header.full_height = spec.full_height;
        header.channel_names = spec.channelnames;
        header.file_type = pixel_type(spec.format);
        for (int c = 0; c < spec.nchannels; ++c) header.channel_file_types.push_back(pixel_type(spec.channelformat(c)));
        header.alpha_channel = spec.alpha_channel;
        header.metadata = metadata_of(spec);
        if (before_pixels) before_pixels(header);
        image.pixels.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
        if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
            return "cannot read pixels: " + input->geterror();
        input->close();
        return "";
    }
};

}  // namespace
}  // namespace isotrace

extern "C" __attribute__((visibility("default"))) const isotrace::ImageCodec* isotrace_image_codec(const char* isotrace_version) {
    static const isotrace::OiioImageCodec codec;
    return std::strcmp(isotrace_version, isotrace::kIsotraceVersion) == 0 ? &codec : nullptr;
}
