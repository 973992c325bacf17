#pragma once
// One Embree device per process, created on first use. Errors reported by Embree are turned into exceptions
// at the call site through check_embree().
#include <embree3/rtcore.h>

#include <atomic>
#include <cstdint>
#include <string>

namespace isotrace {

// Its instruction set is Embree's best for the CPU up to AVX2 (AVX-512 machines run the AVX2 kernels).
RTCDevice embree_device();

// Throws std::runtime_error naming `what` if Embree recorded an error since the last check.
void check_embree(const std::string& what);

// Bytes Embree currently holds (BVHs, geometry buffers it owns), from its memory monitor.
std::int64_t embree_bytes_in_use();

// Sets flush-to-zero and denormals-are-zero on the calling thread (Embree's advice for render threads).
void enable_flush_to_zero();

}  // namespace isotrace
