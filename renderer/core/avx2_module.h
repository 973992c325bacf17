#pragma once
// Kernels built a second time for AVX2 live in modules beside the library (a module, so that the inline functions
// it compiles for AVX2 stay its own and never replace the library's on a CPU without AVX2).
#include "renderer/core/version.h"

namespace isotrace {

// Loads the module `file_name` from beside the loaded libisotrace and returns the address of its `entry`; nullptr
// where the CPU lacks AVX2 or FMA (the modules are built for both) or the module is missing, cannot load or lacks the
// entry (the caller then keeps its baseline build, which computes the same bits). Callers choose once per process.
void* avx2_module_entry(const char* file_name, const char* entry);

// What the module's `entry`, a function Result(const char* isotrace_version), gives this library: its build of a
// kernel when the module was built from this version of isotrace, nullptr when not or where avx2_module_entry finds
// no entry.
template <class Result>
Result avx2_module_build(const char* file_name, const char* entry) {
    const auto function = reinterpret_cast<Result (*)(const char*)>(avx2_module_entry(file_name, entry));
    return function ? function(kIsotraceVersion) : nullptr;
}

}  // namespace isotrace
