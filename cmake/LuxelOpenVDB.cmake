# luxel::openvdb: what linking luxel_octree_vdb takes from OpenVDB (libopenvdb and the TBB and
# Imath libraries it uses). Included by cmake/Dependencies.cmake and by the installed
# luxelConfig.cmake, so the exported luxel::octree_vdb names the same target in both. Debian's
# FindOpenVDB.cmake is not used: it ships its own FindTBB/FindOpenEXR, which would shadow the
# config packages. Sets luxel_openvdb_missing (what was not found) and makes no target then.
set(luxel_openvdb_missing "")
if(NOT TARGET luxel::openvdb)
  find_library(LUXEL_OPENVDB_LIBRARY openvdb)
  find_package(Imath CONFIG QUIET)
  find_package(TBB QUIET)
  if(NOT LUXEL_OPENVDB_LIBRARY)
    string(APPEND luxel_openvdb_missing " libopenvdb")
  endif()
  if(NOT TARGET Imath::Imath)
    string(APPEND luxel_openvdb_missing " Imath")
  endif()
  if(NOT TARGET TBB::tbb)
    string(APPEND luxel_openvdb_missing " TBB")
  endif()
  if(luxel_openvdb_missing STREQUAL "")
    add_library(luxel::openvdb INTERFACE IMPORTED)
    target_link_libraries(luxel::openvdb INTERFACE ${LUXEL_OPENVDB_LIBRARY} TBB::tbb Imath::Imath)
  endif()
endif()
