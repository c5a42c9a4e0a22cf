# Third-party libraries, all from Debian packages (deps/debian-packages.txt). Only what the chosen
# options need is looked for: a CPU-only library build (LUXEL_GPU=OFF, LUXEL_BUILD_VIEWER=OFF)
# needs neither Vulkan, glslc, SDL2 nor Dear ImGui.
find_package(Threads REQUIRED)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(PNG REQUIRED)
find_package(OpenEXR 3 REQUIRED)
# Highway: portable SIMD with run-time dispatch to the best target the CPU has.
find_package(hwy REQUIRED)
if(LUXEL_BUILD_CLI OR LUXEL_BUILD_VIEWER)
  find_package(CLI11 REQUIRED)
endif()
# Vulkan headers (Vulkan-Hpp) and glslc: the GPU backend. The loader is opened at run time.
if(LUXEL_GPU)
  find_package(Vulkan REQUIRED)
  find_program(GLSLC_EXECUTABLE NAMES glslc REQUIRED)
endif()
# SDL2 and Dear ImGui (pkg-config): the viewer's window and panels.
if(LUXEL_BUILD_VIEWER)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(SDL2 REQUIRED IMPORTED_TARGET sdl2)
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
endif()
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
# is found directly (cmake/LuxelOpenVDB.cmake, shared with the installed luxelConfig.cmake), and
# here with the Boost headers its own headers include.
include(${CMAKE_CURRENT_LIST_DIR}/LuxelOpenVDB.cmake)
if(NOT TARGET luxel::openvdb)
  message(FATAL_ERROR "luxel_octree_vdb needs OpenVDB (Debian package libopenvdb-dev): "
                      "${luxel_openvdb_missing}")
endif()
find_path(OPENVDB_INCLUDE_DIR openvdb/openvdb.h REQUIRED)
find_package(Boost 1.70 CONFIG REQUIRED)
add_library(luxel_openvdb INTERFACE IMPORTED)
target_include_directories(luxel_openvdb SYSTEM INTERFACE ${OPENVDB_INCLUDE_DIR})
target_link_libraries(luxel_openvdb INTERFACE luxel::openvdb Boost::headers)
