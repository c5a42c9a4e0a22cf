# LUXEL_FUZZ: every luxel library is compiled with libFuzzer's coverage instrumentation and the
# address and undefined-behaviour sanitizers, so the fuzz targets (fuzz/CMakeLists.txt, which
# add libFuzzer's main) see inside them. Clang only: GCC has no libFuzzer.
if(LUXEL_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "LUXEL_FUZZ needs clang (cmake --preset fuzz uses clang++-16), "
                        "not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
