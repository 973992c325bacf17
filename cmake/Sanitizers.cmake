# Opt-in instrumented builds (separate build directories; see tools/test --sanitize and tools/fuzz).
#   -DISOTRACE_SANITIZE=address,undefined   or   -DISOTRACE_SANITIZE=thread
#   -DISOTRACE_FUZZ=ON   libFuzzer targets in tests/fuzz (clang only), with AddressSanitizer and UBSan.
# Every target of the project is instrumented; the Debian libraries (Embree, TBB, OIIO, OCIO) are not, so bugs
# inside them are not seen, and ThreadSanitizer cannot see TBB's own synchronisation (see docs/reliability.md).
set(ISOTRACE_SANITIZE "" CACHE STRING "Comma-separated -fsanitize= list for every target (empty: none)")
option(ISOTRACE_FUZZ "Build the libFuzzer targets in tests/fuzz (needs clang)" OFF)

set(isotrace_sanitize_list "${ISOTRACE_SANITIZE}")
if(ISOTRACE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "ISOTRACE_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(isotrace_sanitize_list "address,undefined")
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

# Instrumented code runs several times slower (AddressSanitizer ~3x, ThreadSanitizer 5-15x): every test's time
# limit is multiplied by this (isotrace_test_timeout), and so are the few wall-clock budgets and bounds inside
# tests that get it as ISOTRACE_TEST_TIMEOUT_SCALE (tile_renderer_test.cpp, tests/cli/cli_test.sh).
set(ISOTRACE_TEST_TIMEOUT_SCALE 1)
# And their processes hold shadow memory and freed blocks in quarantine beside what isotrace allocates: the end-to-end
# scripts, told by ISOTRACE_TEST_INSTRUMENTED, do not hold a run's peak resident memory to isotrace's bounds there.
set(ISOTRACE_TEST_INSTRUMENTED 0)
if(isotrace_sanitize_list)
  set(ISOTRACE_TEST_TIMEOUT_SCALE 10)
  set(ISOTRACE_TEST_INSTRUMENTED 1)
  add_compile_options(-fsanitize=${isotrace_sanitize_list} -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=${isotrace_sanitize_list})
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND isotrace_sanitize_list MATCHES "address")
    # GCC 12 with AddressSanitizer warns that std::regex's std::function members "may be used uninitialized"
    # (GCC PR 105616, a false positive inside libstdc++): 70 warnings from the files that use <regex>.
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
  if(isotrace_sanitize_list MATCHES "undefined")
    # A finding must fail the test, not just print: UBSan otherwise reports and carries on.
    add_compile_options(-fno-sanitize-recover=undefined)
  endif()
endif()
