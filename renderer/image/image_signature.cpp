#include "renderer/image/image_signature.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <string_view>
#include <vector>

#include "renderer/core/input_error.h"
#include "renderer/core/lower_extension.h"

namespace isotrace {
namespace {

struct Signature {
    std::size_t offset;
    std::string_view bytes;
};

struct ImageFormat {
    const char* name;  // OpenImageIO's
    const char* label;  // for messages
    std::vector<std::string_view> extensions;
    std::vector<Signature> signatures;  // any of them; none: the format has no signature (TGA)
};

using namespace std::string_view_literals;

const std::vector<ImageFormat>& image_formats() {
    static const std::vector<ImageFormat> formats = {
        {"openexr", "OpenEXR", {".exr", ".sxr", ".mxr"}, {{0, "\x76\x2f\x31\x01"sv}}},
        {"png", "PNG", {".png"}, {{0, "\x89PNG\r\n\x1a\n"sv}}},
        {"jpeg", "JPEG", {".jpg", ".jpeg", ".jpe", ".jfif", ".jfi", ".jif"}, {{0, "\xff\xd8\xff"sv}}},
        {"tiff", "TIFF", {".tif", ".tiff", ".tx", ".env", ".sm", ".vsm"},
         {{0, "II*\0"sv}, {0, "MM\0*"sv}, {0, "II+\0"sv}, {0, "MM\0+"sv}}},
        {"hdr", "Radiance HDR", {".hdr", ".rgbe"}, {{0, "#?"sv}}},
        {"bmp", "BMP", {".bmp", ".dib"}, {{0, "BM"sv}}},
        {"gif", "GIF", {".gif"}, {{0, "GIF87a"sv}, {0, "GIF89a"sv}}},
        {"pnm", "PNM", {".ppm", ".pgm", ".pbm", ".pnm", ".pfm"},
         {{0, "P1"sv}, {0, "P2"sv}, {0, "P3"sv}, {0, "P4"sv}, {0, "P5"sv}, {0, "P6"sv}, {0, "Pf"sv}, {0, "PF"sv}}},
        {"psd", "Photoshop", {".psd"}, {{0, "8BPS"sv}}},
        {"webp", "WebP", {".webp"}, {{8, "WEBP"sv}}},
        {"dds", "DDS", {".dds"}, {{0, "DDS "sv}}},
        {"sgi", "SGI", {".sgi", ".rgb", ".rgba", ".bw", ".int", ".inta"}, {{0, "\x01\xda"sv}}},
        {"dpx", "DPX", {".dpx"}, {{0, "SDPX"sv}, {0, "XPDS"sv}}},
        {"cineon", "Cineon", {".cin"}, {{0, "\x80\x2a\x5f\xd7"sv}, {0, "\xd7\x5f\x2a\x80"sv}}},
        {"targa", "Targa", {".tga", ".tpic"}, {}},
    };
    return formats;
}

constexpr std::size_t kSignatureBytes = 16;

[[noreturn]] void refuse(const std::filesystem::path& path, const std::string& problem) {
    throw InputError({path.string(), 0, 0}, "", "cannot read image: " + problem);
}

}  // namespace

std::string image_format_of(const std::filesystem::path& path) {
    const std::string extension = lower_extension(path);
    const auto& formats = image_formats();
    const auto format = std::find_if(formats.begin(), formats.end(), [&](const ImageFormat& f) {
        return std::find(f.extensions.begin(), f.extensions.end(), extension) != f.extensions.end();
    });
    if (format == formats.end()) {
        std::string known;
        for (const ImageFormat& f : formats) known += (known.empty() ? "" : ", ") + std::string(f.extensions.front());
        refuse(path, (extension.empty() ? std::string("the file name has no extension")
                                : "\"" + extension + "\" is not the extension of an image format read here") +
             " (" + known + ")");
    }
    if (format->signatures.empty()) return format->name;
    std::ifstream file(path, std::ios::binary);
    if (!file) return format->name;  // the reader reports files it cannot open
    std::array<char, kSignatureBytes> bytes{};
    file.read(bytes.data(), std::streamsize(bytes.size()));
    const std::string_view start(bytes.data(), std::size_t(file.gcount()));
    for (const Signature& signature : format->signatures)
        if (start.size() >= signature.offset + signature.bytes.size() &&
            start.substr(signature.offset, signature.bytes.size()) == signature.bytes)
            return format->name;
    refuse(path, "its extension names the " + std::string(format->label) +
                     " format, but the file does not start with that format's signature");
}

}  // namespace isotrace
