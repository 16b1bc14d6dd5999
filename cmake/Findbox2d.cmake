# Finds Box2D 2.4 (Debian's libbox2d-dev installs headers and a library but no CMake config).
# Defines the imported target box2d::box2d and box2d_VERSION.
find_path(box2d_INCLUDE_DIR box2d/box2d.h)
find_library(box2d_LIBRARY NAMES box2d)
if(box2d_INCLUDE_DIR AND EXISTS "${box2d_INCLUDE_DIR}/box2d/b2_common.h")
  set(box2d_VERSION "2.4")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(box2d REQUIRED_VARS box2d_LIBRARY box2d_INCLUDE_DIR VERSION_VAR box2d_VERSION)
if(box2d_FOUND AND NOT TARGET box2d::box2d)
  add_library(box2d::box2d UNKNOWN IMPORTED)
  set_target_properties(box2d::box2d PROPERTIES
    IMPORTED_LOCATION "${box2d_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${box2d_INCLUDE_DIR}")
endif()
mark_as_advanced(box2d_INCLUDE_DIR box2d_LIBRARY)
