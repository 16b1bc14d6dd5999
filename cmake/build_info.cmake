# Generates build_info.cpp in the build tree with the facts that go into every output file.
# The git commit and dirty flag are re-read at every build (not only at configure time) by a
# custom target that rewrites the file only when they change.
set(COLLIDE_BUILD_INFO_CPP ${CMAKE_BINARY_DIR}/generated/build_info.cpp)
string(TOUPPER "${CMAKE_BUILD_TYPE}" _bt)
set(COLLIDE_CXX_FLAGS "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_bt}}")
if(COLLIDE_SANITIZE)
  string(APPEND COLLIDE_CXX_FLAGS " -fsanitize=address,undefined")
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
    -DBOX2D_VERSION=${box2d_VERSION}
    -DOPENCL_VERSION=${OpenCL_VERSION_STRING}
    -DPYTHON=${Python3_EXECUTABLE}
    -P ${CMAKE_SOURCE_DIR}/cmake/write_build_info.cmake
  BYPRODUCTS ${COLLIDE_BUILD_INFO_CPP}
  COMMENT "Recording commit and build flags for provenance"
  VERBATIM)
