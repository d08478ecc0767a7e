# Findcmocka: the cmocka unit-test library (only the unit tests need it).
#
#   find_package(cmocka)   ->  target cmocka::cmocka, cmocka_FOUND
#
# Searched first: CMOCKA_ROOT, CMOCKA_DIR (CMake or environment variables
# holding the cmocka install prefix); then the directories pkg-config reports
# for cmocka.pc, CMAKE_PREFIX_PATH and the system. Or give the files:
# -DCMOCKA_INCLUDE_DIR=... -DCMOCKA_LIBRARY=... To build without the unit
# tests although cmocka is installed: -DCMAKE_DISABLE_FIND_PACKAGE_cmocka=ON.

set(_cmocka_hints)
foreach(_d "${CMOCKA_ROOT}" "$ENV{CMOCKA_ROOT}" "${CMOCKA_DIR}" "$ENV{CMOCKA_DIR}")
  if(_d)
    list(APPEND _cmocka_hints "${_d}")
  endif()
endforeach()
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(PC_CMOCKA QUIET cmocka)
endif()

if(_cmocka_hints)
  find_path(CMOCKA_INCLUDE_DIR cmocka.h HINTS ${_cmocka_hints} PATH_SUFFIXES include NO_DEFAULT_PATH)
  find_library(CMOCKA_LIBRARY cmocka HINTS ${_cmocka_hints} PATH_SUFFIXES lib lib64 NO_DEFAULT_PATH)
endif()
find_path(CMOCKA_INCLUDE_DIR cmocka.h HINTS ${PC_CMOCKA_INCLUDE_DIRS})
find_library(CMOCKA_LIBRARY cmocka HINTS ${PC_CMOCKA_LIBRARY_DIRS})
mark_as_advanced(CMOCKA_INCLUDE_DIR CMOCKA_LIBRARY)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(cmocka REQUIRED_VARS CMOCKA_LIBRARY CMOCKA_INCLUDE_DIR
  VERSION_VAR PC_CMOCKA_VERSION)

if(cmocka_FOUND AND NOT TARGET cmocka::cmocka)
  add_library(cmocka::cmocka INTERFACE IMPORTED)
  set_target_properties(cmocka::cmocka PROPERTIES
    INTERFACE_LINK_LIBRARIES "${CMOCKA_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CMOCKA_INCLUDE_DIR}")
endif()
unset(_cmocka_hints)
