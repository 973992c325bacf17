#pragma once
// One Embree device per process, created on first use. Errors reported by Embree are turned into exceptions
// at the call site through check_embree().
#include <embree3/rtcore.h>

#include <atomic>
#include <cstdint>
#include <string>
#include <string_view>

namespace isotrace {

// The widest instruction set Embree may use (its name as Embree's verbose output gives it). Embree's AVX-512
// kernels round hit distances differently from its AVX2 ones, so images, the CPU benchmark's output hashes and MPI
// jobs over mixed machines would differ from machine to machine.
inline constexpr std::string_view kEmbreeIsaCap = "AVX2";

// Its instruction set is Embree's best for the CPU up to kEmbreeIsaCap.
RTCDevice embree_device();

// Throws std::runtime_error naming `what` if Embree recorded an error since the last check.
void check_embree(const std::string& what);

// Bytes Embree currently holds (BVHs, geometry buffers it owns), from its memory monitor.
std::int64_t embree_bytes_in_use();

// Sets flush-to-zero and denormals-are-zero on the calling thread (Embree's advice for render threads).
void enable_flush_to_zero();

}  // namespace isotrace
