# Finds Chipmunk2D 7 (Debian's libchipmunk-dev installs headers and a library but no CMake
# config). Defines the imported target chipmunk::chipmunk and chipmunk_VERSION (read from the
# CP_VERSION_* macros of chipmunk.h, so a different package cannot pass for 7.0.3).
find_path(chipmunk_INCLUDE_DIR chipmunk/chipmunk.h)
find_library(chipmunk_LIBRARY NAMES chipmunk)
if(chipmunk_INCLUDE_DIR AND EXISTS "${chipmunk_INCLUDE_DIR}/chipmunk/chipmunk.h")
  file(STRINGS "${chipmunk_INCLUDE_DIR}/chipmunk/chipmunk.h" _cp_version REGEX "#define CP_VERSION_(MAJOR|MINOR|RELEASE) ")
  string(REGEX REPLACE ".*MAJOR ([0-9]+).*MINOR ([0-9]+).*RELEASE ([0-9]+).*" "\\1.\\2.\\3" chipmunk_VERSION "${_cp_version}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(chipmunk REQUIRED_VARS chipmunk_LIBRARY chipmunk_INCLUDE_DIR VERSION_VAR chipmunk_VERSION)
if(chipmunk_FOUND AND NOT TARGET chipmunk::chipmunk)
  add_library(chipmunk::chipmunk UNKNOWN IMPORTED)
  set_target_properties(chipmunk::chipmunk PROPERTIES
    IMPORTED_LOCATION "${chipmunk_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${chipmunk_INCLUDE_DIR}")
endif()
mark_as_advanced(chipmunk_INCLUDE_DIR chipmunk_LIBRARY)
