# Run at every build (tools/CMakeLists.txt): writes OUTPUT, a header defining ISOTRACE_GIT_COMMIT as the checkout's
# `git rev-parse HEAD`, with "-dirty" when tracked files differ from it, or "unknown" outside a git checkout. The
# header is replaced only when its text changes, so an unchanged commit recompiles nothing.
execute_process(COMMAND git rev-parse HEAD WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE result ERROR_QUIET)
if(NOT result EQUAL 0 OR commit STREQUAL "")
  set(commit "unknown")
else()
  execute_process(COMMAND git status --porcelain --untracked-files=no WORKING_DIRECTORY ${SOURCE_DIR}
                  OUTPUT_VARIABLE changes RESULT_VARIABLE result ERROR_QUIET)
  if(result EQUAL 0 AND NOT changes STREQUAL "")
    string(APPEND commit "-dirty")
  endif()
endif()
file(WRITE ${OUTPUT}.new "// Generated at build time by cmake/WriteBuildCommit.cmake.\n#define ISOTRACE_GIT_COMMIT \"${commit}\"\n")
file(COPY_FILE ${OUTPUT}.new ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.new)
