# Parallel HDF5 (1.10 or newer), in one of two ways:
#   1. pkg-config, under the names in DMHS_HDF5_PKG_CONFIG (Debian's
#      libhdf5-openmpi-dev ships hdf5-openmpi.pc). Skipped when HDF5_ROOT or
#      HDF5_DIR is given (CMake or environment variable), or when
#      DMHS_HDF5_PKG_CONFIG is empty.
#   2. CMake's FindHDF5, which first looks for HDF5's own CMake package file
#      (hdf5-config.cmake: HDF5 built with CMake, e.g. by Spack) and otherwise
#      asks the compiler wrapper h5pcc (parallel preferred over h5cc). Hints:
#      HDF5_ROOT (install prefix), HDF5_DIR (the directory of
#      hdf5-config.cmake), HDF5_C_COMPILER_EXECUTABLE (the h5pcc to use).
# Either way the headers must define H5_HAVE_PARALLEL (checked by compiling a
# test program against them): a serial HDF5 stops the configuration.
# Sets DMHS_HDF5_TARGET (the target to link) and DMHS_HDF5_VERSION.

set(DMHS_HDF5_PKG_CONFIG "hdf5-openmpi" CACHE STRING
  "pkg-config names tried first for parallel HDF5 (empty: use CMake's FindHDF5 only)")

set(_hdf5_hint "")
foreach(_v HDF5_ROOT HDF5_DIR)
  if(${_v})
    set(_hdf5_hint "${_v}=${${_v}}")
  elseif(NOT "$ENV{${_v}}" STREQUAL "")
    set(_hdf5_hint "${_v}=$ENV{${_v}} (environment)")
  endif()
endforeach()

set(DMHS_HDF5_TARGET "")
if(DMHS_HDF5_PKG_CONFIG AND _hdf5_hint STREQUAL "")
  pkg_search_module(HDF5PC QUIET IMPORTED_TARGET ${DMHS_HDF5_PKG_CONFIG})
  if(HDF5PC_FOUND)
    set(DMHS_HDF5_TARGET PkgConfig::HDF5PC)
    set(DMHS_HDF5_VERSION "${HDF5PC_VERSION}")
    message(STATUS "HDF5 ${HDF5PC_VERSION} from pkg-config (${HDF5PC_MODULE_NAME})")
  endif()
endif()

if(NOT DMHS_HDF5_TARGET)
  set(HDF5_PREFER_PARALLEL TRUE)
  find_package(HDF5 1.10 COMPONENTS C)
  if(NOT HDF5_FOUND)
    message(FATAL_ERROR "Parallel HDF5 (1.10 or newer) not found. Set HDF5_ROOT to its install "
      "prefix (where bin/h5pcc, include/hdf5.h and lib/ are), HDF5_DIR to the directory holding "
      "hdf5-config.cmake, or HDF5_C_COMPILER_EXECUTABLE to its h5pcc.")
  endif()
  if(DEFINED HDF5_IS_PARALLEL AND NOT HDF5_IS_PARALLEL)
    message(FATAL_ERROR "The HDF5 found (${HDF5_VERSION}, headers in ${HDF5_INCLUDE_DIRS}) is a "
      "serial build (HDF5_IS_PARALLEL is false); dmhs writes its snapshots and checkpoints with "
      "MPI-IO and needs HDF5 configured with --enable-parallel (CMake: -DHDF5_ENABLE_PARALLEL=ON). "
      "Point HDF5_ROOT at the parallel build.")
  endif()
  set(DMHS_HDF5_TARGET HDF5::HDF5)
  set(DMHS_HDF5_VERSION "${HDF5_VERSION}")
  if(_hdf5_hint)
    message(STATUS "HDF5 ${HDF5_VERSION} from CMake's FindHDF5 (${_hdf5_hint})")
  else()
    message(STATUS "HDF5 ${HDF5_VERSION} from CMake's FindHDF5")
  endif()
endif()

# the authority: what the headers say, compiled with the MPI that dmhs uses
include(CheckCSourceCompiles)
include(CMakePushCheckState)
cmake_push_check_state(RESET)
set(CMAKE_REQUIRED_LIBRARIES ${DMHS_HDF5_TARGET} MPI::MPI_C)
set(CMAKE_REQUIRED_QUIET ON)
unset(DMHS_HDF5_USABLE CACHE)
check_c_source_compiles("#include <hdf5.h>
int main(void) { return H5open() < 0; }" DMHS_HDF5_USABLE)
unset(DMHS_HDF5_HAVE_PARALLEL CACHE)
check_c_source_compiles("#include <hdf5.h>
#ifndef H5_HAVE_PARALLEL
#error serial HDF5
#endif
int main(void) { return 0; }" DMHS_HDF5_HAVE_PARALLEL)
unset(DMHS_HDF5_AT_LEAST_1_10 CACHE)
check_c_source_compiles("#include <hdf5.h>
#if H5_VERS_MAJOR * 100 + H5_VERS_MINOR < 110
#error HDF5 older than 1.10
#endif
int main(void) { return 0; }" DMHS_HDF5_AT_LEAST_1_10)
cmake_pop_check_state()
if(NOT DMHS_HDF5_USABLE)
  message(FATAL_ERROR "HDF5 ${DMHS_HDF5_VERSION} (${DMHS_HDF5_TARGET}): a program calling H5open() "
    "does not compile and link against it with this compiler and MPI; the configure log under "
    "CMakeFiles/ has the compiler's words. HDF5 must be built with the MPI that dmhs uses.")
endif()
if(NOT DMHS_HDF5_HAVE_PARALLEL)
  message(FATAL_ERROR "HDF5 ${DMHS_HDF5_VERSION} (${DMHS_HDF5_TARGET}) is a serial build: its "
    "H5pubconf.h does not define H5_HAVE_PARALLEL. dmhs writes its snapshots and checkpoints with "
    "MPI-IO and needs HDF5 configured with --enable-parallel (CMake: -DHDF5_ENABLE_PARALLEL=ON), "
    "built with the same MPI. Point HDF5_ROOT at such a build.")
endif()
if(NOT DMHS_HDF5_AT_LEAST_1_10)
  message(FATAL_ERROR "HDF5 ${DMHS_HDF5_VERSION} (${DMHS_HDF5_TARGET}) is older than 1.10, which dmhs needs.")
endif()
unset(_hdf5_hint)
