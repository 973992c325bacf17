#pragma once
// 64-bit FNV-1a: a small, dependency-free hash for detecting changed or corrupted bytes (not for security).
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace isotrace {

inline constexpr std::uint64_t kFnv1aOffset = 0xcbf29ce484222325ull;

// Continues the hash `h` over `bytes`: fnv1a_64(b, fnv1a_64(a)) == fnv1a_64(a + b).
inline std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t h = kFnv1aOffset) {
    for (const char c : bytes) {
        h ^= std::uint8_t(c);
        h *= 0x100000001b3ull;
    }
    return h;
}

// A hash as 16 lower-case hex digits, as reports and messages print it.
inline std::string hex64(std::uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016" PRIx64, value);
    return text;
}

}  // namespace isotrace
