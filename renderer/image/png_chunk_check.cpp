#include "renderer/image/png_chunk_check.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "renderer/core/input_error.h"
#include "renderer/core/printable.h"

namespace isotrace {
namespace {

constexpr char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
constexpr std::uint64_t kChunkOverhead = 12;  // length, type and CRC around the data

std::uint32_t big_endian_u32(const unsigned char* bytes) {
    return std::uint32_t(bytes[0]) << 24 | std::uint32_t(bytes[1]) << 16 | std::uint32_t(bytes[2]) << 8 | bytes[3];
}

}  // namespace

void check_png_chunk_sizes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    char signature[sizeof kSignature] = {};
    if (!file.read(signature, sizeof signature) || std::memcmp(signature, kSignature, sizeof kSignature) != 0) return;
    file.seekg(0, std::ios::end);
    const std::uint64_t size = std::uint64_t(file.tellg());
    // Each chunk moves on by at least 12 bytes, so the walk ends within size / 12 steps.
    for (std::uint64_t at = sizeof kSignature; at + 8 <= size;) {
        unsigned char header[8];
        file.seekg(std::streamoff(at));
        if (!file.read(reinterpret_cast<char*>(header), sizeof header)) return;  // libpng reports short files
        const std::uint64_t length = big_endian_u32(header);
        const std::string type(reinterpret_cast<const char*>(header) + 4, 4);
        if (length + kChunkOverhead > size - at)
            throw InputError({path.string(), 0, 0}, "",
                             "corrupt PNG: the \"" + printable(type) + "\" chunk at byte " + std::to_string(at) +
                                 " claims " + std::to_string(length) + " bytes, more than the " +
                                 std::to_string(size - at) + " left in the file");
        if (type == "IEND") return;
        at += kChunkOverhead + length;
    }
}

}  // namespace isotrace
