#pragma once
// How this isotrace binary was built, recorded by CMake when the build was configured (tools/CMakeLists.txt):
// the compiler, its flags and the git commit of the checkout ("unknown" outside a git checkout; a commit made
// after configuring shows only after CMake runs again).
#include <string>

namespace isotrace::cli {

struct BuildDescription {
    std::string compiler;    // CMAKE_CXX_COMPILER_ID and version: "GNU 12.2.0"
    std::string flags;       // CMAKE_CXX_FLAGS with the build type's flags
    std::string build_type;  // "Release"
    std::string commit;      // git rev-parse HEAD at configure time
};

BuildDescription build_description();

}  // namespace isotrace::cli
