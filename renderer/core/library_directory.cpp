#include "renderer/core/library_directory.h"

#include <dlfcn.h>

namespace isotrace {

std::filesystem::path library_directory() {
    Dl_info info{};
    if (!dladdr(reinterpret_cast<void*>(&library_directory), &info) || !info.dli_fname) return {};
    return std::filesystem::path(info.dli_fname).parent_path();
}

}  // namespace isotrace
