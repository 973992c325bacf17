#pragma once
// How this isotrace binary was built (tools/CMakeLists.txt): the compiler and its flags, recorded when CMake
// configured the build, and the git commit of the checkout, recorded at every build ("unknown" outside a git
// checkout, "-dirty" appended when tracked files had uncommitted changes).
#include <string>

namespace isotrace::cli {

struct BuildDescription {
    std::string compiler;    // CMAKE_CXX_COMPILER_ID and version: "GNU 12.2.0"
    std::string flags;       // CMAKE_CXX_FLAGS with the build type's flags
    std::string build_type;  // "Release"
    std::string commit;      // git rev-parse HEAD when built, e.g. "0123…cdef" or "0123…cdef-dirty"
};

BuildDescription build_description();

}  // namespace isotrace::cli
