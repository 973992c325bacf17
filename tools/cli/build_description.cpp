#include "tools/cli/build_description.h"

// Defined for this file only (tools/CMakeLists.txt), so that no other object changes with each commit.
#ifndef ISOTRACE_COMPILER
#error "tools/CMakeLists.txt defines ISOTRACE_COMPILER, ISOTRACE_CXX_FLAGS, ISOTRACE_BUILD_TYPE, ISOTRACE_GIT_COMMIT"
#endif

namespace isotrace::cli {

BuildDescription build_description() {
    return {ISOTRACE_COMPILER, ISOTRACE_CXX_FLAGS, ISOTRACE_BUILD_TYPE, ISOTRACE_GIT_COMMIT};
}

}  // namespace isotrace::cli
