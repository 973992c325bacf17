# Package test driver: cmake -D BUILD_DIR=... -D CONSUMER_SOURCE_DIR=... -D WORK_DIR=... -D SCENE=...
#                            [-D GENERATOR=...] [-D CXX_COMPILER=...] [-D BUILD_TYPE=...] [-D SANITIZE=...]
#                            -P run_consumer_test.cmake
# 1. cmake --install BUILD_DIR into WORK_DIR/prefix (WORK_DIR is emptied first)
# 2. configures and builds the consumer project against that prefix only
# 3. runs the consumer on SCENE and the installed isotrace CLI with --version and a small render to PNG
cmake_minimum_required(VERSION 3.25)

foreach(variable BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR SCENE)
  if(NOT DEFINED ${variable} OR "${${variable}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer_test.cmake: -D ${variable}=... is required")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()

# Runs a command, echoes it, and stops the test with its output when it fails.
function(run_step description)
  message(STATUS "==> ${description}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "${description} failed (${result}):\n${command}\n${output}")
  endif()
  set(step_output "${output}" PARENT_SCOPE)
endfunction()

set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/consumer-build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

run_step("installing ${BUILD_DIR} into ${prefix}"
  "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}" --config "${BUILD_TYPE}")

set(configure_arguments -S "${CONSUMER_SOURCE_DIR}" -B "${consumer_build}"
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
if(GENERATOR)
  list(APPEND configure_arguments -G "${GENERATOR}")
endif()
if(CXX_COMPILER)
  list(APPEND configure_arguments "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
if(SANITIZE)
  # An instrumented library needs the sanitizer runtime loaded first: the consumer is linked with it too.
  list(APPEND configure_arguments "-DCMAKE_CXX_FLAGS=-fsanitize=${SANITIZE}"
       "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=${SANITIZE}")
endif()
run_step("configuring the consumer" "${CMAKE_COMMAND}" ${configure_arguments})
string(REGEX MATCH "isotrace package: [^\n]*" found "${step_output}")
message(STATUS "${found}")
if(NOT found MATCHES "isotrace package: ${prefix}/")
  message(FATAL_ERROR "the consumer did not find the installed package under ${prefix}:\n${step_output}")
endif()

run_step("building the consumer" "${CMAKE_COMMAND}" --build "${consumer_build}" --config "${BUILD_TYPE}")

find_program(consumer isotrace_consumer PATHS "${consumer_build}" "${consumer_build}/${BUILD_TYPE}" NO_DEFAULT_PATH
             NO_CACHE)
if(NOT consumer)
  message(FATAL_ERROR "no isotrace_consumer executable in ${consumer_build}")
endif()
run_step("rendering ${SCENE} with the consumer" "${CMAKE_COMMAND}" -E env --unset=OCIO "${consumer}" "${SCENE}")
message(STATUS "${step_output}")
if(NOT step_output MATCHES "mean pixel value [0-9]")
  message(FATAL_ERROR "unexpected consumer output:\n${step_output}")
endif()

# Without $OCIO the installed library must find the config installed beside it (located from the library's
# own path, so the install is relocatable), not the source tree's copy.
file(GLOB_RECURSE installed_ocio "${prefix}/*/isotrace.ocio")
if(NOT installed_ocio)
  message(FATAL_ERROR "the OCIO config was not installed under ${prefix}")
endif()
if(NOT step_output MATCHES "OCIO config ${installed_ocio}")
  message(FATAL_ERROR "the consumer did not use the installed OCIO config ${installed_ocio}:\n${step_output}")
endif()

# The installed command line finds its library through its install RPATH.
run_step("running the installed CLI" "${prefix}/bin/isotrace" --version)
if(NOT step_output MATCHES "isotrace [0-9]+\\.[0-9]+\\.[0-9]+")
  message(FATAL_ERROR "unexpected output of ${prefix}/bin/isotrace --version: ${step_output}")
endif()
# The installed CLI writes images through the modules installed beside the library: PNG through the image
# module, EXR through the EXR writer module.
foreach(format_and_module "png;libisotrace_oiio.so" "exr;libisotrace_exr.so")
  list(GET format_and_module 0 format)
  list(GET format_and_module 1 module)
  run_step("rendering a ${format} with the installed CLI"
    "${prefix}/bin/isotrace" render "${SCENE}" --res 8x8 --spp 1 --quiet -o "${WORK_DIR}/installed.${format}")
  file(GLOB installed_module "${prefix}/*/${module}")
  if(NOT installed_module OR NOT EXISTS "${WORK_DIR}/installed.${format}")
    message(FATAL_ERROR "the installed ${module} is missing or the installed CLI wrote no ${format}")
  endif()
endforeach()
message(STATUS "package test passed")
