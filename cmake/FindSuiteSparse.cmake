# Finds the SuiteSparse libraries tether uses (UMFPACK, CHOLMOD and their
# orderings) as installed by Debian's libsuitesparse-dev, which ships no CMake
# package. Defines SuiteSparse::SuiteSparse.
find_path(SuiteSparse_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse)
set(_ss_libs umfpack cholmod amd colamd camd ccolamd suitesparseconfig)
set(SuiteSparse_LIBRARIES)
foreach(_l IN LISTS _ss_libs)
  find_library(SuiteSparse_${_l}_LIBRARY ${_l})
  list(APPEND SuiteSparse_LIBRARIES ${SuiteSparse_${_l}_LIBRARY})
  list(APPEND _ss_vars SuiteSparse_${_l}_LIBRARY)
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse REQUIRED_VARS SuiteSparse_INCLUDE_DIR ${_ss_vars})
if(SuiteSparse_FOUND AND NOT TARGET SuiteSparse::SuiteSparse)
  add_library(SuiteSparse::SuiteSparse INTERFACE IMPORTED)
  set_target_properties(SuiteSparse::SuiteSparse PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${SuiteSparse_LIBRARIES}")
endif()
