#pragma once
// The narrow interface between libisotrace and its two image modules, the only code that links image libraries.
// OpenImageIO's Debian package pulls in ~260 shared libraries whose loading and relocation cost every process
// ~0.4 s before main(), so libisotrace does not link it: image_codec() loads the image module (libisotrace_oiio.so,
// installed beside libisotrace) with dlopen the first time an image is decoded, or encoded in a format other than
// EXR. EXR, what every render writes, is encoded by the EXR writer module (libisotrace_exr.so, OpenEXR alone: ~10
// libraries), which writes the bytes the image module would. Nothing here names a library's type, and the modules
// are built from the same sources, so plain C++ types cross the boundary. Most code wants the functions built on
// it: write_image_file() (image_writer.h), read_image_file() (image_reader.h).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "renderer/image/image_metadata.h"

namespace isotrace {

// Pixel data types, in memory or as stored in a file.
enum class PixelType { UInt8, Int8, UInt16, Int16, UInt32, Int32, UInt64, Int64, Half, Float, Double, Other };

inline bool is_floating_point(PixelType type) {
    return type == PixelType::Half || type == PixelType::Float || type == PixelType::Double;
}

// An image to encode. The file's format is chosen from the extension of the path it is encoded for.
struct ImageEncoding {
    int width = 0, height = 0;
    std::vector<std::string> channel_names;  // one per channel, in the order of `pixels`
    // Interleaved pixels, row 0 at the top: width * height * channel_names.size() values of `memory_type`
    // (Float or UInt8).
    const void* pixels = nullptr;
    PixelType memory_type = PixelType::Float;
    PixelType file_type = PixelType::Float;  // how channels are stored
    std::vector<PixelType> channel_file_types;  // if not empty: per channel, overriding file_type
    int alpha_channel = -1;
    // The data window's origin inside the full (display) window; full size 0 = the data window's size.
    int x = 0, y = 0, full_width = 0, full_height = 0;
    std::string compression;  // e.g. "zip"; empty = the format's default
    // Attributes in this order: text as text, reals as 32-bit floats, integers as 32-bit integers (as text
    // beyond that range), float lists as float arrays. Formats keep what they can (PNG: text only).
    ImageMetadata metadata;
};

// What a file says about its first image, before any pixel is read.
struct ImageHeader {
    std::string format;  // OpenImageIO's name of the file's format ("openexr", "png", ...)
    int width = 0, height = 0;
    int x = 0, y = 0;  // data window origin
    int full_x = 0, full_y = 0, full_width = 0, full_height = 0;  // full (display) window
    std::vector<std::string> channel_names;  // the reader's channel order (EXR: R, G, B, A first)
    PixelType file_type = PixelType::Other;  // the file's pixel type (for mixed files the reader's choice)
    std::vector<PixelType> channel_file_types;  // one per channel
    int alpha_channel = -1;  // -1: none
    // Every attribute: integers as int64, real scalars as double, float arrays and matrices as float lists,
    // anything else as text.
    ImageMetadata metadata;
};

struct DecodedImage {
    ImageHeader header;
    std::vector<float> pixels;  // interleaved, all channels as float (integer formats scaled to 0..1), row 0 top
};

// Called with the header before the pixels are allocated and read: may throw to refuse the image (the memory
// budget charges the pixels' memory here).
using BeforePixels = std::function<void(const ImageHeader&)>;

class ImageEncoder {
public:
    virtual ~ImageEncoder() = default;
    // The file bytes of `image` in the format of `path`'s extension (nothing is written to `path`). Throws
    // std::runtime_error "cannot write <path>: <reason>".
    virtual std::vector<unsigned char> encode(const std::filesystem::path& path, const ImageEncoding& image) const = 0;
};

class ImageCodec : public ImageEncoder {
public:
    // Reads the first 2-D image of `path` with the reader of `format` (OpenImageIO's format name; no other reader
    // is tried) into `image`; returns "" or what is wrong with the file (it cannot be opened or read, is not 2-D,
    // has no channels). Exceptions from `before_pixels` pass through.
    virtual std::string decode(const std::filesystem::path& path, const std::string& format,
                               const BeforePixels& before_pixels, DecodedImage& image) const = 0;
};

// The module exports this C function: it returns its codec, or nullptr if `isotrace_version` is not the version
// it was built for (a module left over from another install).
using ImageCodecEntry = const ImageCodec* (*)(const char* isotrace_version);
inline constexpr const char* kImageCodecEntry = "isotrace_image_codec";

// The EXR writer module (libisotrace_exr.so, OpenEXR alone) exports this one: every .exr file is encoded there, so
// that writing EXR does not load OpenImageIO, whose many libraries take a render's worth of CPU time to link
// (docs/decisions.md, "Image I/O in a module loaded with dlopen").
using ImageEncoderEntry = const ImageEncoder* (*)(const char* isotrace_version);
inline constexpr const char* kImageEncoderEntry = "isotrace_image_encoder";

// The module's codec, loaded once, on first use, from the directory of the loaded libisotrace (thread-safe).
// Throws std::runtime_error naming the module's path if it is missing or cannot be loaded.
const ImageCodec& image_codec();
// Whether image_codec() has loaded the module in this process.
bool image_codec_loaded();
// Resident memory that loading the image module adds to a process: OpenImageIO's libraries (measured,
// docs/reliability.md), charged by the first image read under a memory budget.
inline constexpr std::uint64_t kImageModuleResidentBytes = std::uint64_t(128) << 20;
// The encoder for files like `path`: the EXR writer module for .exr, image_codec() for any other (each loaded
// once, on first use, like image_codec()).
const ImageEncoder& image_encoder_for(const std::filesystem::path& path);

// Loads the codec from the module at `module_path` (image_codec() passes the one beside libisotrace).
// Throws std::runtime_error naming the path and the loader's reason when that fails.
const ImageCodec& load_image_codec(const std::filesystem::path& module_path);
// The same for the EXR writer module.
const ImageEncoder& load_exr_encoder(const std::filesystem::path& module_path);

// Loads the encoders that files like `outputs` need (image_encoder_for()) on a thread of their own, so that their
// dynamic linking (long for OpenImageIO's many libraries: docs/decisions.md) overlaps other work (a render: with a
// core to spare, it then costs no wall time). image_encoder_for() called before the load ends waits for it; a load that failed calls
// `on_failure` from that thread and is tried again by the next call, which throws its error. The destructor waits
// for the thread. While a module loads, the loader's lock is held and any thread being created waits: start this
// after the threads it should overlap.
class ImageCodecPreload {
public:
    ImageCodecPreload(std::vector<std::filesystem::path> outputs, std::function<void()> on_failure);
    ~ImageCodecPreload();
    ImageCodecPreload(const ImageCodecPreload&) = delete;
    ImageCodecPreload& operator=(const ImageCodecPreload&) = delete;

private:
    std::thread thread_;
};

}  // namespace isotrace
