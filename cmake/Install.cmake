# `cmake --install`: the libraries of luxel_library() (cmake/Library.cmake), the public headers,
# the CMake package (find_package(luxel) -> luxel::<name>) and luxel.pc. The executables install
# themselves (apps/*/CMakeLists.txt).
include(CMakePackageConfigHelpers)

set(LUXEL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/luxel)
get_property(luxel_libraries GLOBAL PROPERTY LUXEL_LIBRARIES)
install(TARGETS ${luxel_libraries} EXPORT luxelTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/luxel DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT luxelTargets NAMESPACE luxel:: DESTINATION ${LUXEL_CMAKE_DIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/luxelConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/luxelConfig.cmake
                              INSTALL_DESTINATION ${LUXEL_CMAKE_DIR})
# SameMajorVersion: find_package(luxel 1.2) accepts 1.2 and any later 1.x, whose API only grows,
# but not 2.x, which may break it; an older 1.x may lack what the caller uses, so it is refused too
# (AnyNewerVersion would also accept the next major version, and with it a broken build). While
# luxel is 0.x, CMake treats every 0.y as the same major version.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/luxelConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/luxelConfig.cmake ${PROJECT_BINARY_DIR}/luxelConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/LuxelOpenVDB.cmake
        DESTINATION ${LUXEL_CMAKE_DIR})

# luxel.pc: the libraries in link order (each before what it uses), found relative to the .pc
# file itself, so the tree can be installed under any --prefix.
set(luxel_link_order luxel_scene luxel_octree_vdb luxel_octree luxel_post_voxel luxel_voxel
                     luxel_post luxel_gi2d luxel_gpu luxel_core)
set(luxel_unordered ${luxel_libraries})
list(REMOVE_ITEM luxel_unordered ${luxel_link_order})
if(luxel_unordered)
  message(FATAL_ERROR "cmake/Install.cmake: add ${luxel_unordered} to luxel_link_order (luxel.pc)")
endif()
set(LUXEL_PC_LIBS "")
foreach(library ${luxel_link_order})
  string(APPEND LUXEL_PC_LIBS " -l${library}")
endforeach()
string(STRIP "${LUXEL_PC_LIBS}" LUXEL_PC_LIBS)
set(LUXEL_PC_DL "")
foreach(library ${CMAKE_DL_LIBS})
  string(APPEND LUXEL_PC_DL " -l${library}")
endforeach()
file(RELATIVE_PATH LUXEL_PC_PREFIX_FROM_PCDIR /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
configure_file(${CMAKE_CURRENT_LIST_DIR}/luxel.pc.in ${PROJECT_BINARY_DIR}/luxel.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/luxel.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
