#include "renderer/core/avx2_module.h"

#include <dlfcn.h>

#include "renderer/core/library_directory.h"

namespace isotrace {

void* avx2_module_entry(const char* file_name, const char* entry) {
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) return nullptr;
    void* module = dlopen((library_directory() / file_name).c_str(), RTLD_NOW | RTLD_LOCAL);
    return module ? dlsym(module, entry) : nullptr;
}

}  // namespace isotrace
