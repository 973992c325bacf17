#pragma once
// Four 32-bit lanes in one 16-byte register (GCC/clang vector extensions: SSE2 on any x86-64, no intrinsics).
// Arithmetic, shifts and comparisons act per lane; a scalar operand is broadcast.
#include <concepts>
#include <cstdint>

namespace isotrace {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));
using Uint4 = std::uint32_t __attribute__((vector_size(16)));

// One uint32_t, or four in the lanes of a Uint4: for bit manipulations written once for both.
template <class Bits>
concept Uint32Bits = std::same_as<Bits, std::uint32_t> || std::same_as<Bits, Uint4>;

}  // namespace isotrace
