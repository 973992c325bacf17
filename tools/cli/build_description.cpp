#include "tools/cli/build_description.h"

// Written at every build (cmake/WriteBuildCommit.cmake), in the build tree: ISOTRACE_GIT_COMMIT.
#include "tools/cli/build_commit.h"

// Defined for this file only (tools/CMakeLists.txt), so that no other object changes with each commit.
#ifndef ISOTRACE_COMPILER
#error "tools/CMakeLists.txt defines ISOTRACE_COMPILER, ISOTRACE_CXX_FLAGS, ISOTRACE_BUILD_TYPE"
#endif

namespace isotrace::cli {

BuildDescription build_description() {
    return {ISOTRACE_COMPILER, ISOTRACE_CXX_FLAGS, ISOTRACE_BUILD_TYPE, ISOTRACE_GIT_COMMIT};
}

}  // namespace isotrace::cli
