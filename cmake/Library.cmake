# luxel_library(<target> <name>): makes a luxel static library installable and usable as
# luxel::<name>, the same name in a find_package(luxel) consumer (the export set, EXPORT_NAME)
# and in a project that adds luxel with add_subdirectory (an ALIAS). Public headers come from
# include/ in the source tree and from <prefix>/include once installed; src/ stays private.
function(luxel_library target name)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  target_compile_features(${target} PUBLIC cxx_std_20)  # the public headers are C++20
  add_library(luxel::${name} ALIAS ${target})
  target_include_directories(${target}
    PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${PROJECT_SOURCE_DIR}/src)
  set_property(GLOBAL APPEND PROPERTY LUXEL_LIBRARIES ${target})
endfunction()
