#pragma once
// The machine and build a benchmark ran on, for isotrace bench's JSON and HTML report.
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace isotrace::cli {

// {"cpu", "cores", "embree_isa", "embree_native_packets", "blob_march_isa" (the build of the blob cell queries
//  this process uses, blob_cell_queries.h), "embree_version", "compiler", "flags", "build_type", "isotrace_version",
//  "commit"}.
nlohmann::json machine_description();

// The "model name" of /proc/cpuinfo; "unknown" where there is none.
std::string cpu_model();

// The widest instruction set Embree 3 dispatches to on this CPU. Embree 3 has no device property for the ISA it
// selected; it picks the best of the targets it was built for that the CPU supports (Debian's build: SSE2,
// SSE4.2, AVX, AVX2, AVX-512), so this reads the same CPU flags, and the native packet widths the device reports
// (RTC_DEVICE_PROPERTY_NATIVE_RAY{4,8,16}_SUPPORTED) are given beside it.
std::string embree_isa();

// Whether Embree's kernels for `isa` (as embree_isa names it) come before its AVX2 ones: SSE2, SSE4.2 and AVX, which
// test triangle edges without fused multiply-adds and so decide a few hits at shared edges differently.
bool embree_isa_before_avx2(std::string_view isa);

// The best ISA named by a /proc/cpuinfo "flags" line: "AVX512SKX", "AVX2", "AVX", "SSE4.2", "SSE2" or "unknown".
std::string isa_from_cpu_flags(const std::string& flags);

}  // namespace isotrace::cli
