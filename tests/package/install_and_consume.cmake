# ctest script (package.install_and_consume): installs the built tree into a temporary prefix and
# uses it as a project outside luxel would:
#   1. cmake --install BUILD_DIR --prefix <tmp>/prefix, and the files a user needs are there;
#   2. find_package(luxel) with every component, a version check and an unknown component;
#   3. tests/package/consumer (find_package(luxel COMPONENTS gi2d), luxel::gi2d) is configured,
#      built and run: its HRC solve must match the analytic fluence of a disk light;
#   4. the same main.cpp compiled with the flags of `pkg-config --static --cflags --libs luxel`.
# The temporary directory is removed whether the test passes or fails.
# Inputs: BUILD_DIR, CONSUMER_DIR, CXX_COMPILER, GENERATOR, LIBDIR (CMAKE_INSTALL_LIBDIR) and
# CONSUMER_FLAGS (compile and link flags for the consumer: the sanitizers of a sanitizer build).
foreach(input BUILD_DIR CONSUMER_DIR CXX_COMPILER GENERATOR LIBDIR CONSUMER_FLAGS)
  if(NOT DEFINED ${input})
    message(FATAL_ERROR "install_and_consume.cmake needs -D${input}=...")
  endif()
endforeach()

string(RANDOM LENGTH 8 suffix)
set(work ${BUILD_DIR}/package-test-${suffix})
set(prefix ${work}/prefix)
file(REMOVE_RECURSE ${work})
file(MAKE_DIRECTORY ${work})

# Ends the test with `message`, after removing the temporary directory.
macro(fail message)
  file(REMOVE_RECURSE ${work})
  message(FATAL_ERROR "${message}")
endmacro()

# Runs a command; fails the test with its output unless it exits 0. The output is in `output`.
macro(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT rc EQUAL 0)
    fail("${what} failed (${rc}):\n${output}")
  endif()
endmacro()

# 1. Install.
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(file ${LIBDIR}/libluxel_core.a ${LIBDIR}/libluxel_gi2d.a ${LIBDIR}/libluxel_scene.a
             ${LIBDIR}/libluxel_octree_vdb.a ${LIBDIR}/cmake/luxel/luxelConfig.cmake
             ${LIBDIR}/cmake/luxel/luxelConfigVersion.cmake ${LIBDIR}/cmake/luxel/luxelTargets.cmake
             ${LIBDIR}/pkgconfig/luxel.pc include/luxel/gi2d/hrc_solver.h include/luxel/gpu/context.h)
  if(NOT EXISTS ${prefix}/${file})
    fail("cmake --install did not install ${file}")
  endif()
endforeach()
if(EXISTS ${prefix}/include/luxel/gpu/shaders OR EXISTS ${prefix}/${LIBDIR}/libluxel_warnings.a)
  fail("cmake --install installed build-only files")
endif()

set(configure_args -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release
                   -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
                   "-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_FLAGS}")
separate_arguments(consumer_flags UNIX_COMMAND "${CONSUMER_FLAGS}")

# 2. find_package(luxel) as a user may call it: every component (every third-party package), a
#    major version luxel is not (SameMajorVersion), a component luxel does not have.
file(WRITE ${work}/probe/CMakeLists.txt [=[
cmake_minimum_required(VERSION 3.25)
project(luxel_probe LANGUAGES CXX)
find_package(luxel 0.1 REQUIRED)
foreach(name core gpu post gi2d voxel octree octree_vdb scene post_voxel)
  if(NOT TARGET luxel::${name})
    message(FATAL_ERROR "find_package(luxel) gave no luxel::${name}")
  endif()
endforeach()
message(STATUS "probe: luxel ${luxel_VERSION} from ${luxel_DIR}")
find_package(luxel 99 QUIET)
message(STATUS "probe: version 99 found=${luxel_FOUND}")
find_package(luxel QUIET COMPONENTS no_such_component)
message(STATUS "probe: unknown component found=${luxel_FOUND}")
]=])
run("find_package(luxel) probe" ${CMAKE_COMMAND} -S ${work}/probe -B ${work}/probe-build
    ${configure_args})
foreach(expected "probe: luxel 0.1.0 from ${prefix}/${LIBDIR}/cmake/luxel"
                 "probe: version 99 found=0" "probe: unknown component found=0")
  string(FIND "${output}" "${expected}" at)
  if(at EQUAL -1)
    fail("find_package(luxel) probe: expected '${expected}' in:\n${output}")
  endif()
endforeach()

# 3. The consumer project, with CMake.
run("configuring tests/package/consumer" ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${work}/build
    ${configure_args})
run("building tests/package/consumer" ${CMAKE_COMMAND} --build ${work}/build)
run("running the consumer" ${work}/build/consumer)
message(STATUS "CMake consumer: ${output}")
if(NOT output MATCHES "luxel consumer: fluence inside")
  fail("the consumer printed no fluence:\n${output}")
endif()

# 4. The same program with pkg-config.
find_program(PKG_CONFIG_EXECUTABLE NAMES pkg-config pkgconf)
if(NOT PKG_CONFIG_EXECUTABLE)
  fail("pkg-config is not installed, so luxel.pc cannot be checked")
endif()
set(ENV{PKG_CONFIG_PATH} ${prefix}/${LIBDIR}/pkgconfig)
run("pkg-config luxel" ${PKG_CONFIG_EXECUTABLE} --static --cflags --libs luxel)
string(STRIP "${output}" flags)
message(STATUS "pkg-config --static --cflags --libs luxel: ${flags}")
# The include directory is found relative to luxel.pc (${pcfiledir}), so it is the prefix's.
string(REGEX MATCH "-I([^ ]+/include)( |$)" include_flag "${flags}")
file(REAL_PATH "${CMAKE_MATCH_1}" include_dir)
file(REAL_PATH "${prefix}/include" prefix_include_dir)
if(NOT include_dir STREQUAL prefix_include_dir OR NOT flags MATCHES "-lluxel_gi2d .*-lluxel_core")
  fail("luxel.pc does not point into ${prefix} or lists the libraries out of order: ${flags}")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
run("compiling the consumer with pkg-config's flags" ${CXX_COMPILER} -std=c++20 -O2
    ${consumer_flags} ${CONSUMER_DIR}/main.cpp -o ${work}/consumer-pkg-config ${flags})
run("running the pkg-config consumer" ${work}/consumer-pkg-config)
message(STATUS "pkg-config consumer: ${output}")

file(REMOVE_RECURSE ${work})
