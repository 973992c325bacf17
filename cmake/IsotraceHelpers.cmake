# Folder-level helpers: every folder lists its own sources and tests; the top level never names a file.

# How the library and its modules compile their arithmetic. The math functions' error reporting through errno is never
# read: without it a square root is one instruction, not a test and a branch to libm after it. Results are the same
# to the last bit (errno is all it changes).
set(ISOTRACE_MATH_OPTIONS -fno-math-errno)

# The warnings every target compiles with. GCC alone also gets:
# -Wno-restrict: a false positive on std::string concatenation (GCC bug 105329);
# -Wno-psabi: notes that 32-byte vectors (Double4, eight-float lanes) pass differently with and without AVX. No such
#   value crosses between code built for different instruction sets: the AVX2 modules export only their entry point
#   and keep their inline functions to themselves.
set(ISOTRACE_WARNINGS -Wall -Wextra $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict> $<$<CXX_COMPILER_ID:GNU>:-Wno-psabi>)

# Adds library sources (paths relative to the calling folder) to the isotrace library.
function(isotrace_sources)
  foreach(source IN LISTS ARGN)
    target_sources(isotrace PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}/${source}")
  endforeach()
endfunction()

# Adds GoogleTest sources (beside the code they test) to the single isotrace_tests executable.
function(isotrace_tests)
  foreach(source IN LISTS ARGN)
    set_property(GLOBAL APPEND PROPERTY ISOTRACE_TEST_SOURCES "${CMAKE_CURRENT_SOURCE_DIR}/${source}")
  endforeach()
endfunction()

# Sets `variable` to a test time limit of `seconds`, scaled for sanitizer builds (cmake/Sanitizers.cmake).
function(isotrace_test_timeout variable seconds)
  math(EXPR scaled "${seconds} * ${ISOTRACE_TEST_TIMEOUT_SCALE}")
  set(${variable} ${scaled} PARENT_SCOPE)
endfunction()

# A MODULE library `target` from `source` that libisotrace loads with dlopen from its own directory: only its entry
# point is exported (hidden visibility: fewer symbols to relocate when it loads, and its inline functions stay its
# own), and building the library builds it.
function(isotrace_module target source)
  add_library(${target} MODULE ${source})
  target_compile_options(${target} PRIVATE ${ISOTRACE_WARNINGS} ${ISOTRACE_MATH_OPTIONS})
  target_include_directories(${target} PRIVATE ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/include)
  set_target_properties(${target} PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  add_dependencies(isotrace ${target})
endfunction()

# An image module `target` built from `source` and linked with the image libraries `ARGN`, loaded on first use
# (renderer/image/image_codec.h): every program linking libisotrace may read or write images.
function(isotrace_image_module target source)
  isotrace_module(${target} ${source})
  target_link_libraries(${target} PRIVATE ${ARGN})
endfunction()

# A kernel built a second time, for AVX2 and FMA without contraction (so that it rounds as the library's baseline
# build of the same source does; only the bounds that renderer/math/fused_bounds.h marks fuse): the module `target`
# from `source` with the compile definitions `ARGN`, loaded where the CPU has AVX2 and FMA
# (renderer/core/avx2_module.h). Its inline functions, compiled for AVX2, never replace the library's; its calls into
# the library resolve against the libisotrace the process has loaded.
function(isotrace_avx2_module target source)
  isotrace_module(${target} ${source})
  target_compile_options(${target} PRIVATE -mavx2 -mfma -ffp-contract=off)
  target_compile_definitions(${target} PRIVATE ${ARGN})
endfunction()

# A Google Benchmark executable `name` from `source` (and any further sources in ARGN, such as a test oracle it
# times), built on request (EXCLUDE_FROM_ALL) and not run by ctest:
# cmake --build <dir> --target <name> && <dir>/bin/<name>
function(isotrace_benchmark name source)
  find_package(benchmark REQUIRED)
  add_executable(${name} EXCLUDE_FROM_ALL ${source} ${ARGN})
  target_link_libraries(${name} PRIVATE isotrace benchmark::benchmark)
endfunction()
