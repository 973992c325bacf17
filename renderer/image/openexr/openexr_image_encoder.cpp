// The EXR writer module (libisotrace_exr.so): ImageEncoder for .exr files with OpenEXR, writing the header that
// the image module's OpenImageIO writes for the same image (tested byte for byte against it): OpenImageIO's names
// of the standard attributes are translated (DateTime → capDate, now when absent; chromaticities → a
// Chromaticities attribute), everything else keeps its name and type.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFloatVectorAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <Imath/half.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <thread>
#include <variant>

#include "renderer/core/version.h"
#include "renderer/image/image_codec.h"

namespace isotrace {
namespace {

// OpenEXR writes through a stream: this one keeps the bytes in memory (the caller writes the file atomically).
class MemoryStream final : public Imf::OStream {
public:
    explicit MemoryStream(std::vector<unsigned char>& bytes) : Imf::OStream("memory"), bytes_(bytes) {}
    void write(const char c[], int n) override {
        const std::size_t end = std::size_t(position_) + std::size_t(n);
        if (bytes_.size() < end) bytes_.resize(end);
        std::memcpy(bytes_.data() + position_, c, std::size_t(n));
        position_ = end;
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = position; }

private:
    std::vector<unsigned char>& bytes_;
    uint64_t position_ = 0;
};

Imf::PixelType exr_type(PixelType type) {
    switch (type) {
        case PixelType::Half: return Imf::HALF;
        case PixelType::Float: return Imf::FLOAT;
        default: throw std::runtime_error("EXR channels are written as half or float");
    }
}

Imf::Compression exr_compression(const std::string& name) {
    static const std::pair<const char*, Imf::Compression> kNames[] = {
        {"", Imf::ZIP_COMPRESSION},     {"none", Imf::NO_COMPRESSION}, {"rle", Imf::RLE_COMPRESSION},
        {"zips", Imf::ZIPS_COMPRESSION}, {"zip", Imf::ZIP_COMPRESSION}, {"piz", Imf::PIZ_COMPRESSION},
        {"pxr24", Imf::PXR24_COMPRESSION}, {"b44", Imf::B44_COMPRESSION}, {"b44a", Imf::B44A_COMPRESSION},
        {"dwaa", Imf::DWAA_COMPRESSION}, {"dwab", Imf::DWAB_COMPRESSION}};
    for (const auto& [known, compression] : kNames)
        if (name == known) return compression;
    throw std::runtime_error("unknown EXR compression \"" + name + "\"");
}

// "YYYY:MM:DD HH:MM:SS", local time: what OpenImageIO writes when the image names no DateTime.
std::string now_as_date_time() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &local);
    return text;
}

void add_metadata(Imf::Header& header, const ImageMetadata& metadata) {
    bool dated = false;
    for (const auto& [name, value] : metadata.entries) {
        if (const auto* text = std::get_if<std::string>(&value)) {
            dated = dated || name == "DateTime";
            header.insert(name == "DateTime" ? "capDate" : name, Imf::StringAttribute(*text));
        } else if (const auto* real = std::get_if<double>(&value)) {
            header.insert(name, Imf::FloatAttribute(float(*real)));
        } else if (const auto* integer = std::get_if<std::int64_t>(&value)) {
            const std::variant<int, std::string> stored = integer_attribute(*integer);
            if (const int* small = std::get_if<int>(&stored)) header.insert(name, Imf::IntAttribute(*small));
            else header.insert(name, Imf::StringAttribute(std::get<std::string>(stored)));
        } else {
            // Float lists as OpenImageIO stores them: 2 and 3 floats as vectors, 9 and 16 as matrices, the
            // working space's primaries as chromaticities, any other length as a float vector.
            const auto& f = std::get<std::vector<float>>(value);
            if (name == "chromaticities" && f.size() == 8)
                header.insert(name, Imf::ChromaticitiesAttribute(
                                        Imf::Chromaticities({f[0], f[1]}, {f[2], f[3]}, {f[4], f[5]}, {f[6], f[7]})));
            else if (f.size() == 2)
                header.insert(name, Imf::V2fAttribute({f[0], f[1]}));
            else if (f.size() == 3)
                header.insert(name, Imf::V3fAttribute({f[0], f[1], f[2]}));
            else if (f.size() == 9)
                header.insert(name, Imf::M33fAttribute({f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8]}));
            else if (f.size() == 16)
                header.insert(name, Imf::M44fAttribute({f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8], f[9],
                                                        f[10], f[11], f[12], f[13], f[14], f[15]}));
            else
                header.insert(name, Imf::FloatVectorAttribute(f));
        }
    }
    if (!dated) header.insert("capDate", Imf::StringAttribute(now_as_date_time()));
}

class OpenExrImageEncoder final : public ImageEncoder {
public:
    std::vector<unsigned char> encode(const std::filesystem::path& path, const ImageEncoding& image) const override {
        try {
            if (image.memory_type != PixelType::Float) throw std::runtime_error("EXR pixels come as float");
            const int full_width = image.full_width > 0 ? image.full_width : image.width;
            const int full_height = image.full_height > 0 ? image.full_height : image.height;
            Imf::Header header(Imath::Box2i({0, 0}, {full_width - 1, full_height - 1}),
                               Imath::Box2i({image.x, image.y},
                                            {image.x + image.width - 1, image.y + image.height - 1}));
            header.compression() = exr_compression(image.compression);
            add_metadata(header, image.metadata);
            const std::size_t channels = image.channel_names.size();
            // A slice addresses pixel (x, y) of the data window: its base is the first pixel less the window's origin.
            const auto slice = [&](Imf::PixelType type, const void* first, std::size_t x_stride) {
                const std::size_t y_stride = x_stride * std::size_t(image.width);
                char* base = static_cast<char*>(const_cast<void*>(first)) -
                             std::ptrdiff_t(image.x) * std::ptrdiff_t(x_stride) -
                             std::ptrdiff_t(image.y) * std::ptrdiff_t(y_stride);
                return Imf::Slice(type, base, x_stride, y_stride);
            };
            Imf::FrameBuffer frame;
            // OpenEXR writes a channel from memory of its own type: half channels are converted here, each to a
            // plane of its own (Imath's rounding, as OpenImageIO converts).
            const std::size_t pixel_count = std::size_t(image.width) * std::size_t(image.height);
            std::vector<std::vector<Imath::half>> half_planes;
            half_planes.reserve(channels);
            for (std::size_t c = 0; c < channels; ++c) {
                const PixelType file = image.channel_file_types.empty() ? image.file_type : image.channel_file_types[c];
                const Imf::PixelType type = exr_type(file);
                header.channels().insert(image.channel_names[c], Imf::Channel(type));
                const float* source = static_cast<const float*>(image.pixels) + c;
                if (type == Imf::FLOAT) {
                    frame.insert(image.channel_names[c], slice(Imf::FLOAT, source, channels * sizeof(float)));
                    continue;
                }
                std::vector<Imath::half>& plane = half_planes.emplace_back(pixel_count);
                for (std::size_t i = 0; i < pixel_count; ++i) plane[i] = Imath::half(source[i * channels]);
                frame.insert(image.channel_names[c], slice(Imf::HALF, plane.data(), sizeof(Imath::half)));
            }
            std::vector<unsigned char> bytes;
            MemoryStream stream(bytes);
            {
                // Lines are compressed on OpenEXR's own threads, one per core (as OpenImageIO has it: the render's
                // threads are idle by now); the bytes do not depend on the count. The offset table is written
                // when the file closes.
                static const int threads = [] {
                    Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency())));
                    return Imf::globalThreadCount();
                }();
                Imf::OutputFile file(stream, header, threads);
                file.setFrameBuffer(frame);
                file.writePixels(image.height);
            }
            return bytes;
        } catch (const std::exception& error) {
            throw std::runtime_error("cannot write " + path.string() + ": " + error.what());
        }
    }
};

}  // namespace
}  // namespace isotrace

extern "C" __attribute__((visibility("default"))) const isotrace::ImageEncoder* isotrace_image_encoder(
    const char* isotrace_version) {
    static const isotrace::OpenExrImageEncoder encoder;
    return std::strcmp(isotrace_version, isotrace::kIsotraceVersion) == 0 ? &encoder : nullptr;
}
