# FindMETIS: METIS 5 (metis.h, libmetis).
#
#   find_package(METIS 5 REQUIRED)   ->  target METIS::METIS, METIS_VERSION
#
# Searched first, in this order: METIS_ROOT, METIS_DIR (each a CMake variable
# or an environment variable holding the METIS install prefix, as HPC modules
# often set one of them) and PETSc's own prefix (PETSC_DIR/PETSC_ARCH, where
# PETSc --download-metis puts it); then CMAKE_PREFIX_PATH and the system.
# Or give the files themselves: -DMETIS_INCLUDE_DIR=... -DMETIS_LIBRARY=...
# METIS 5.2 built on its own may need libGKlib as well: it is linked when
# found beside libmetis (METIS_GKLIB_LIBRARY).

set(_metis_hints)
foreach(_d "${METIS_ROOT}" "$ENV{METIS_ROOT}" "${METIS_DIR}" "$ENV{METIS_DIR}")
  if(_d)
    list(APPEND _metis_hints "${_d}")
  endif()
endforeach()
if(PETSC_DIR)
  list(APPEND _metis_hints "${PETSC_DIR}/${PETSC_ARCH}")
endif()

if(_metis_hints)
  find_path(METIS_INCLUDE_DIR metis.h HINTS ${_metis_hints} PATH_SUFFIXES include NO_DEFAULT_PATH)
  find_library(METIS_LIBRARY metis HINTS ${_metis_hints} PATH_SUFFIXES lib lib64 NO_DEFAULT_PATH)
endif()
find_path(METIS_INCLUDE_DIR metis.h)
find_library(METIS_LIBRARY metis)
if(METIS_LIBRARY)
  get_filename_component(_metis_libdir "${METIS_LIBRARY}" DIRECTORY)
  find_library(METIS_GKLIB_LIBRARY GKlib HINTS "${_metis_libdir}" NO_DEFAULT_PATH)
endif()
mark_as_advanced(METIS_INCLUDE_DIR METIS_LIBRARY METIS_GKLIB_LIBRARY)

set(METIS_VERSION "")
if(METIS_INCLUDE_DIR AND EXISTS "${METIS_INCLUDE_DIR}/metis.h")
  file(STRINGS "${METIS_INCLUDE_DIR}/metis.h" _metis_ver
       REGEX "^#define[ \t]+METIS_VER_(MAJOR|MINOR|SUBMINOR)[ \t]+[0-9]+")
  foreach(_part MAJOR MINOR SUBMINOR)
    set(_metis_${_part} 0)
    foreach(_line IN LISTS _metis_ver)
      if(_line MATCHES "METIS_VER_${_part}[ \t]+([0-9]+)")
        set(_metis_${_part} "${CMAKE_MATCH_1}")
      endif()
    endforeach()
  endforeach()
  set(METIS_VERSION "${_metis_MAJOR}.${_metis_MINOR}.${_metis_SUBMINOR}")
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(METIS
  REQUIRED_VARS METIS_LIBRARY METIS_INCLUDE_DIR
  VERSION_VAR METIS_VERSION
  REASON_FAILURE_MESSAGE "set METIS_DIR (or METIS_ROOT) to the METIS install prefix, or METIS_INCLUDE_DIR and METIS_LIBRARY to metis.h's directory and the library")

if(METIS_FOUND AND NOT TARGET METIS::METIS)
  add_library(METIS::METIS UNKNOWN IMPORTED)
  set_target_properties(METIS::METIS PROPERTIES
    IMPORTED_LOCATION "${METIS_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${METIS_INCLUDE_DIR}")
  if(METIS_GKLIB_LIBRARY)
    set_property(TARGET METIS::METIS APPEND PROPERTY INTERFACE_LINK_LIBRARIES "${METIS_GKLIB_LIBRARY}")
  endif()
endif()
unset(_metis_hints)
unset(_metis_libdir)
unset(_metis_ver)
