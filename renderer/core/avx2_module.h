#pragma once
// Kernels built a second time for AVX2 live in modules beside the library (a module, so that the inline functions
// it compiles for AVX2 stay its own and never replace the library's on a CPU without AVX2).
namespace isotrace {

// Loads the module `file_name` from beside the loaded libisotrace and returns the address of its `entry`; nullptr
// where the CPU lacks AVX2 or the module is missing, cannot load or lacks the entry (the caller then keeps its
// baseline build, which computes the same bits). Callers choose once per process.
void* avx2_module_entry(const char* file_name, const char* entry);

}  // namespace isotrace
