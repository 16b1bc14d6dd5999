# Generates build_info.cpp in the build tree with the facts that go into every output file.
# The git commit and dirty flag are re-read at every build (not only at configure time) by a
# custom target that rewrites the file only when they change.
set(COLLIDE_BUILD_INFO_CPP ${CMAKE_BINARY_DIR}/generated/build_info.cpp)
string(TOUPPER "${CMAKE_BUILD_TYPE}" _bt)
set(COLLIDE_CXX_FLAGS "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_bt}}")
if(COLLIDE_SANITIZE)
  string(APPEND COLLIDE_CXX_FLAGS " -fsanitize=address,undefined")
endif()
# Box2D's version, recorded once (box2d_version): the installed package's own version. The
# library's b2_version cannot be trusted (Box2D 2.4.1 still says 2.4.0) and Findbox2d.cmake can
# only tell 2.4 from the headers, so the package's version is read here, at configure time: from
# its pkg-config file, else from dpkg (Debian's package version, e.g. 2.4.1-3), else "unknown".
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(COLLIDE_BOX2D_PC QUIET box2d)
endif()
if(COLLIDE_BOX2D_PC_VERSION)
  set(COLLIDE_BOX2D_PACKAGE_VERSION "${COLLIDE_BOX2D_PC_VERSION}")
else()
  execute_process(COMMAND dpkg-query -W -f=\${Version} libbox2d-dev
    OUTPUT_VARIABLE COLLIDE_BOX2D_PACKAGE_VERSION OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0 OR COLLIDE_BOX2D_PACKAGE_VERSION STREQUAL "")
    set(COLLIDE_BOX2D_PACKAGE_VERSION "unknown")
  endif()
endif()
add_custom_target(collide_build_info
  COMMAND ${CMAKE_COMMAND}
    -DSOURCE_DIR=${CMAKE_SOURCE_DIR}
    -DOUTPUT=${COLLIDE_BUILD_INFO_CPP}
    "-DCOMPILER=${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}"
    "-DFLAGS=${COLLIDE_CXX_FLAGS} -Wall -Wextra"
    -DBUILD_TYPE=${CMAKE_BUILD_TYPE}
    -DVERSION=${PROJECT_VERSION}
    -DHDF5_VERSION=${HDF5_VERSION}
    -DGSL_VERSION=${GSL_VERSION}
    -DEIGEN_VERSION=${Eigen3_VERSION}
    -DCLI11_VERSION=${CLI11_VERSION}
    -DTOMLPP_VERSION=${tomlplusplus_VERSION}
    -DBOX2D_VERSION=${COLLIDE_BOX2D_PACKAGE_VERSION}
    -DOPENCL_VERSION=${OpenCL_VERSION_STRING}
    -DPYTHON=${Python3_EXECUTABLE}
    -P ${CMAKE_SOURCE_DIR}/cmake/write_build_info.cmake
  BYPRODUCTS ${COLLIDE_BUILD_INFO_CPP}
  COMMENT "Recording commit and build flags for provenance"
  VERBATIM)
