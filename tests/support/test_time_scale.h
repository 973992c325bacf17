#pragma once
// The few wall-clock budgets and limits inside unit tests are multiplied by this: instrumented builds run 3-15
// times slower. ISOTRACE_TEST_TIMEOUT_SCALE is cmake/Sanitizers.cmake's (1 in normal builds, 10 in sanitizer
// builds), defined for the test files that include this header (tests/CMakeLists.txt).
namespace isotrace::testing {

inline constexpr double kTestTimeScale = ISOTRACE_TEST_TIMEOUT_SCALE;

}  // namespace isotrace::testing
