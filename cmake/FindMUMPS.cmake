# Finds sequential MUMPS (double precision) as installed by Debian's
# libmumps-seq-dev, which ships no CMake package. Defines MUMPS::MUMPS.
find_path(MUMPS_INCLUDE_DIR dmumps_c.h)
find_path(MUMPS_MPISEQ_INCLUDE_DIR mpi.h PATH_SUFFIXES mumps_seq NO_DEFAULT_PATH PATHS /usr/include /usr/local/include)
set(_mumps_libs dmumps_seq mumps_common_seq pord_seq mpiseq_seq)
set(MUMPS_LIBRARIES)
foreach(_l IN LISTS _mumps_libs)
  find_library(MUMPS_${_l}_LIBRARY ${_l})
  list(APPEND MUMPS_LIBRARIES ${MUMPS_${_l}_LIBRARY})
  list(APPEND _mumps_vars MUMPS_${_l}_LIBRARY)
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MUMPS REQUIRED_VARS MUMPS_INCLUDE_DIR MUMPS_MPISEQ_INCLUDE_DIR ${_mumps_vars})
if(MUMPS_FOUND AND NOT TARGET MUMPS::MUMPS)
  add_library(MUMPS::MUMPS INTERFACE IMPORTED)
  set_target_properties(MUMPS::MUMPS PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR};${MUMPS_MPISEQ_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${MUMPS_LIBRARIES}")
endif()
