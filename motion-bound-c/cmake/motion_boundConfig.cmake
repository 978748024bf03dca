# CMake package configuration of motion-bound-c, installed by install.sh as
# <prefix>/lib/cmake/motion_bound/motion_boundConfig.cmake. In a C or C++ project:
#   find_package(motion_bound 0.1 REQUIRED)      # with -DCMAKE_PREFIX_PATH=<prefix>
# (the version is checked by motion_boundConfigVersion.cmake: 0.1.z serves a request for 0.1)
#   target_link_libraries(app PRIVATE motion_bound::motion_bound)
# motion_bound::motion_bound is the static library (with the system libraries it needs);
# motion_bound::shared is the shared one.
get_filename_component(_motion_bound_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET motion_bound::motion_bound)
  add_library(motion_bound::motion_bound STATIC IMPORTED)
  set_target_properties(motion_bound::motion_bound PROPERTIES
    IMPORTED_LOCATION "${_motion_bound_prefix}/lib/libmotion_bound_c.a"
    INTERFACE_INCLUDE_DIRECTORIES "${_motion_bound_prefix}/include"
    INTERFACE_LINK_LIBRARIES "pthread;dl;m")
endif()
if(NOT TARGET motion_bound::shared)
  add_library(motion_bound::shared SHARED IMPORTED)
  set_target_properties(motion_bound::shared PROPERTIES
    IMPORTED_LOCATION "${_motion_bound_prefix}/lib/libmotion_bound_c.so"
    INTERFACE_INCLUDE_DIRECTORIES "${_motion_bound_prefix}/include")
endif()
set(motion_bound_FOUND TRUE)
unset(_motion_bound_prefix)
