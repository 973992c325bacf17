# Included by tests/CMakeLists.txt (tests are registered once CTest is enabled).
# End-to-end runs under mpirun (2 ranks on this machine, also as root): images bit-identical to one process with
# both splits, a killed rank, bad input. Small renders, so that they stay in the default test run.
if(ISOTRACE_MPI AND MPIEXEC_EXECUTABLE)
  set(mpi_cases identical_samples identical_tiles identical_aovs identical_surfaces killed_rank bad_input bench)
  isotrace_test_timeout(mpi_test_timeout 180)
  foreach(case IN LISTS mpi_cases)
    add_test(NAME mpi_${case}
             COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/distributed_test.sh $<TARGET_FILE:isotrace_cli>
                     ${CMAKE_SOURCE_DIR} ${MPIEXEC_EXECUTABLE} ${case})
    set_tests_properties(mpi_${case} PROPERTIES LABELS "cli;mpi" TIMEOUT ${mpi_test_timeout} RUN_SERIAL TRUE
                                                ENVIRONMENT ISOTRACE_TEST_TIMEOUT_SCALE=${ISOTRACE_TEST_TIMEOUT_SCALE})
  endforeach()
endif()
