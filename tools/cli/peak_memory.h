#pragma once
// The process's peak resident memory, reset between benchmark workloads so that each reports its own peak.
#include <cstdint>

namespace isotrace::cli {

// Resets the kernel's high-water mark of resident memory (writes 5 to /proc/self/clear_refs, Linux ≥ 4.0).
// Returns false where that is not possible; the peak then covers the whole process so far.
bool reset_peak_memory();

// Peak resident bytes since the last reset: VmHWM of /proc/self/status, else getrusage's ru_maxrss.
std::uint64_t peak_memory_bytes();

}  // namespace isotrace::cli
