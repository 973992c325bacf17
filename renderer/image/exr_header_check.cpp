#include "renderer/image/exr_header_check.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

constexpr std::uint32_t kExrMagic = 20000630;  // 76 2f 31 01, little-endian
constexpr std::uint32_t kMultiPartFlag = 0x1000;
// Header attributes are small (names and types up to 255 bytes, values a few kB); reading more than this many
// bytes of headers is never needed to find a bad size.
constexpr std::size_t kMaxHeaderBytes = std::size_t(16) << 20;

std::uint32_t little_endian_u32(const std::vector<char>& bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = value << 8 | std::uint8_t(bytes[at + std::size_t(i)]);
    return value;
}

}  // namespace

void check_exr_header_sizes(const std::filesystem::path& path) {
    const auto fail = [&](const std::string& problem) { throw InputError({path.string(), 0, 0}, "", problem); };
    std::ifstream file(path, std::ios::binary);
    if (!file) return;  // OpenImageIO reports files it cannot open
    std::error_code error;
    const std::uintmax_t file_size = std::filesystem::file_size(path, error);
    if (error) return;
    std::vector<char> bytes(std::size_t(std::min<std::uintmax_t>(file_size, kMaxHeaderBytes)));
    file.read(bytes.data(), std::streamsize(bytes.size()));
    bytes.resize(std::size_t(file.gcount()));
    if (bytes.size() < 8 || little_endian_u32(bytes, 0) != kExrMagic) return;
    const bool multi_part = (little_endian_u32(bytes, 4) & kMultiPartFlag) != 0;

    // A NUL-terminated string at `at`; returns the position after its NUL.
    const auto string_end = [&](std::size_t at, const std::string& what) {
        for (std::size_t i = at; i < bytes.size(); ++i)
            if (bytes[i] == '\0') return i + 1;
        fail("corrupt OpenEXR header: " + what + " runs past the end of the file");
        return bytes.size();
    };
    // Past the bytes read: the end of the file, or (for a file larger than kMaxHeaderBytes) nothing more to check.
    const auto ran_out = [&](std::size_t at) {
        if (at < bytes.size()) return false;
        if (bytes.size() == file_size) fail("corrupt OpenEXR header: the file ends inside the header");
        return true;
    };
    std::size_t at = 8;
    for (;;) {  // one header, or for multi-part files headers until an empty one
        if (ran_out(at)) return;
        if (bytes[at] == '\0') {
            if (!multi_part || at == 8) fail("corrupt OpenEXR header: no attributes");
            return;
        }
        while (bytes[at] != '\0') {  // attributes: name, type, int32 size, value
            const std::size_t name_start = at;
            const std::size_t type_start = string_end(at, "an attribute name");
            const std::string name(bytes.data() + name_start, type_start - 1 - name_start);
            const std::size_t size_at = string_end(type_start, "the type of attribute \"" + name + "\"");
            if (ran_out(size_at + 3)) return;
            const std::uint32_t size = little_endian_u32(bytes, size_at);
            const std::uintmax_t left = file_size - (size_at + 4);
            if (size > left || std::int32_t(size) < 0)
                fail("corrupt OpenEXR header: attribute \"" + name + "\" claims " + std::to_string(size) +
                     " bytes, but only " + std::to_string(left) + " follow it in the file");
            at = size_at + 4 + size;
            if (ran_out(at)) return;
        }
        ++at;  // the header's terminating NUL
        if (!multi_part) return;
    }
}

}  // namespace isotrace
