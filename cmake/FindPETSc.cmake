# FindPETSc: PETSc through its pkg-config file (PETSc.pc, or petsc.pc).
#
#   find_package(PETSc 3.18 REQUIRED)   ->  target PkgConfig::PETSC, PETSc_VERSION
#
# Where the file is looked for:
#   * PETSC_DIR and PETSC_ARCH, as CMake variables (-DPETSC_DIR=...) or, when
#     those are not given, from the environment: the file must then be in
#     $PETSC_DIR/$PETSC_ARCH/lib/pkgconfig (a build inside the PETSc source
#     tree) or, with PETSC_ARCH empty, in $PETSC_DIR/lib/pkgconfig (a
#     --prefix install, Spack, most HPC modules). A PETSC_DIR without either
#     file is an error, not a silent fall-back to another PETSc.
#   * without PETSC_DIR: pkg-config's own search path (PKG_CONFIG_PATH, then
#     the system's, e.g. Debian's petsc-dev), plus CMAKE_PREFIX_PATH.
# The PETSc found must use MPI (not PETSc's MPIUNI stub) and double-precision
# reals (PETSc's default); both are checked by compiling a test program.

set(PETSC_DIR "$ENV{PETSC_DIR}" CACHE PATH
  "PETSc install prefix or source tree (empty: pkg-config's search path)")
set(PETSC_ARCH "$ENV{PETSC_ARCH}" CACHE STRING
  "PETSc configuration inside PETSC_DIR (empty for a --prefix install)")

find_package(PkgConfig)
if(NOT PKG_CONFIG_FOUND)
  message(FATAL_ERROR "PETSc is found through its pkg-config file, and pkg-config (or pkgconf) "
    "was not found: install it, or point PKG_CONFIG_EXECUTABLE at it.")
endif()

set(_petsc_pc_dir "")
set(_petsc_saved_pkg_config_path "$ENV{PKG_CONFIG_PATH}")
if(PETSC_DIR)
  if(PETSC_ARCH)
    set(_petsc_pc_dir "${PETSC_DIR}/${PETSC_ARCH}/lib/pkgconfig")
  else()
    set(_petsc_pc_dir "${PETSC_DIR}/lib/pkgconfig")
  endif()
  if(NOT EXISTS "${_petsc_pc_dir}/PETSc.pc" AND NOT EXISTS "${_petsc_pc_dir}/petsc.pc")
    message(FATAL_ERROR "PETSC_DIR=${PETSC_DIR} PETSC_ARCH=${PETSC_ARCH}: there is no "
      "PETSc.pc or petsc.pc in ${_petsc_pc_dir}. Set PETSC_ARCH to the configuration "
      "PETSc was built in (a directory of PETSC_DIR such as arch-linux-c-opt), leave it empty "
      "for a --prefix install, or unset PETSC_DIR to use pkg-config's search path.")
  endif()
  # first on the path, so this PETSc wins over any other one pkg-config can see
  if(_petsc_saved_pkg_config_path STREQUAL "")
    set(ENV{PKG_CONFIG_PATH} "${_petsc_pc_dir}")
  else()
    set(ENV{PKG_CONFIG_PATH} "${_petsc_pc_dir}:${_petsc_saved_pkg_config_path}")
  endif()
endif()

# pkg-config's results are cached: forget them when PETSc is to come from elsewhere
if(NOT "${_petsc_pc_dir}" STREQUAL "${DMHS_PETSC_PC_DIR_USED}")
  unset(__pkg_config_checked_PETSC CACHE)
  get_cmake_property(_petsc_cache CACHE_VARIABLES)
  foreach(_v IN LISTS _petsc_cache)
    if(_v MATCHES "^pkgcfg_lib_PETSC_")
      unset(${_v} CACHE)
    endif()
  endforeach()
  set(DMHS_PETSC_PC_DIR_USED "${_petsc_pc_dir}" CACHE INTERNAL "")
endif()

# the file in PETSC_DIR by its own name, so that no other PETSc.pc on the path is taken
if(PETSC_DIR AND EXISTS "${_petsc_pc_dir}/PETSc.pc")
  set(_petsc_names PETSc)
elseif(PETSC_DIR)
  set(_petsc_names petsc)
else()
  set(_petsc_names PETSc petsc)
endif()
set(_petsc_modules)
foreach(_n IN LISTS _petsc_names)
  if(PETSc_FIND_VERSION)
    list(APPEND _petsc_modules "${_n}>=${PETSc_FIND_VERSION}")
  else()
    list(APPEND _petsc_modules "${_n}")
  endif()
endforeach()
pkg_search_module(PETSC QUIET IMPORTED_TARGET ${_petsc_modules})
if(PETSC_FOUND AND PETSC_DIR)
  pkg_get_variable(_petsc_pcfiledir ${PETSC_MODULE_NAME} pcfiledir)
  get_filename_component(_petsc_a "${_petsc_pcfiledir}" REALPATH)
  get_filename_component(_petsc_b "${_petsc_pc_dir}" REALPATH)
  if(NOT _petsc_a STREQUAL _petsc_b)
    message(FATAL_ERROR "PETSC_DIR=${PETSC_DIR} PETSC_ARCH=${PETSC_ARCH}: pkg-config took "
      "${PETSC_MODULE_NAME}.pc from ${_petsc_pcfiledir} instead of ${_petsc_pc_dir}.")
  endif()
endif()
set(ENV{PKG_CONFIG_PATH} "${_petsc_saved_pkg_config_path}")

if(PETSC_FOUND)
  set(PETSc_VERSION "${PETSC_VERSION}")
  # MPI and double-precision reals: the solver needs both
  include(CheckCSourceCompiles)
  include(CMakePushCheckState)
  cmake_push_check_state(RESET)
  set(CMAKE_REQUIRED_LIBRARIES PkgConfig::PETSC)
  if(TARGET MPI::MPI_C)
    list(APPEND CMAKE_REQUIRED_LIBRARIES MPI::MPI_C)
  endif()
  set(CMAKE_REQUIRED_QUIET ON)
  unset(DMHS_PETSC_WITH_MPI CACHE)
  check_c_source_compiles("#include <petscsys.h>
#if defined(PETSC_HAVE_MPIUNI)
#error PETSc was configured without MPI
#endif
int main(void) { return 0; }" DMHS_PETSC_WITH_MPI)
  unset(DMHS_PETSC_REAL_DOUBLE CACHE)
  check_c_source_compiles("#include <petscsys.h>
#if !defined(PETSC_USE_REAL_DOUBLE)
#error PETSc reals are not double precision
#endif
int main(void) { return 0; }" DMHS_PETSC_REAL_DOUBLE)
  cmake_pop_check_state()
  if(NOT DMHS_PETSC_WITH_MPI)
    message(FATAL_ERROR "PETSc ${PETSC_VERSION} in ${PETSC_PREFIX} does not compile with MPI here: "
      "either it was configured without MPI (--with-mpi=0; dmhs needs MPI), or its headers do not "
      "build (the configure log under CMakeFiles/ has the compiler's words).")
  endif()
  if(NOT DMHS_PETSC_REAL_DOUBLE)
    message(FATAL_ERROR "PETSc ${PETSC_VERSION} in ${PETSC_PREFIX} does not use double-precision "
      "reals: dmhs needs PETSc configured with --with-precision=double (PETSc's default).")
  endif()
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(PETSc
  REQUIRED_VARS PETSC_LINK_LIBRARIES
  VERSION_VAR PETSc_VERSION
  REASON_FAILURE_MESSAGE "no PETSc.pc or petsc.pc (version ${PETSc_FIND_VERSION} or newer) found by pkg-config: set PETSC_DIR (and PETSC_ARCH for a build inside the PETSc source tree), or add the directory holding the file to PKG_CONFIG_PATH")
unset(_petsc_cache)
unset(_petsc_names)
unset(_petsc_modules)
unset(_petsc_pcfiledir)
unset(_petsc_a)
unset(_petsc_b)
unset(_petsc_pc_dir)
unset(_petsc_saved_pkg_config_path)
