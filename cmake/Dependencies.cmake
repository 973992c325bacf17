# Every dependency comes from Debian 12 packages (tools/install-dependencies installs them).
find_package(embree 3.13 REQUIRED)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(tinyobjloader CONFIG REQUIRED)
# Debian's OpenImageIO CMake target names a missing /usr/include/opencv4 and OpenColorIO's config lives in
# an unusual place: pkg-config works for both.
find_package(PkgConfig REQUIRED)
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)
pkg_check_modules(OCIO REQUIRED IMPORTED_TARGET OpenColorIO)
# The machine's topology (sockets, cores, SMT, caches) for isotrace benchmark results.
pkg_check_modules(HWLOC REQUIRED IMPORTED_TARGET hwloc)
# Distributed rendering (renderer/distributed, docs/distributed.md): on when an MPI implementation is found
# (Debian: libopenmpi-dev); the build works without it.
find_package(MPI COMPONENTS CXX QUIET)
option(ISOTRACE_MPI "Distributed rendering over MPI (mpirun, srun)" ${MPI_CXX_FOUND})
if(ISOTRACE_MPI)
  find_package(MPI REQUIRED COMPONENTS CXX)
endif()
