# Third-party libraries, all from Debian packages (deps/debian-packages.txt).
find_package(Threads REQUIRED)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(PNG REQUIRED)
find_package(OpenEXR 3 REQUIRED)
# Highway: portable SIMD with run-time dispatch to the best target the CPU has.
find_package(hwy REQUIRED)
# Vulkan headers (Vulkan-Hpp) and glslc: the GPU backend. The loader is opened at run time.
find_package(Vulkan REQUIRED)
find_program(GLSLC_EXECUTABLE NAMES glslc REQUIRED)
if(LUXEL_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(LUXEL_BUILD_TESTS OR LUXEL_BUILD_BENCH)
  find_package(embree 3 REQUIRED)  # oracle and yardstick for the voxel DDA (tests, benchmarks)
endif()
if(LUXEL_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
# OpenVDB: import and export of octrees (luxel_octree_vdb only). Debian's FindOpenVDB.cmake ships
# its own FindTBB/FindOpenEXR, which would shadow the config packages found above, so libopenvdb
# is found directly, with the TBB, Imath (half) and Boost headers its own headers include.
find_path(OPENVDB_INCLUDE_DIR openvdb/openvdb.h REQUIRED)
find_library(OPENVDB_LIBRARY openvdb REQUIRED)
find_package(Imath CONFIG REQUIRED)
find_package(Boost 1.70 CONFIG REQUIRED)
add_library(luxel_openvdb INTERFACE IMPORTED)
target_include_directories(luxel_openvdb SYSTEM INTERFACE ${OPENVDB_INCLUDE_DIR})
target_link_libraries(luxel_openvdb INTERFACE ${OPENVDB_LIBRARY} TBB::tbb Imath::Imath
                                              Boost::headers)
