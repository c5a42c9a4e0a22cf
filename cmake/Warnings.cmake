# Compiler warnings and sanitizers as INTERFACE targets that every luxel target links.
add_library(luxel_warnings INTERFACE)
target_compile_options(luxel_warnings INTERFACE -Wall -Wextra -Wshadow -Wnon-virtual-dtor -Wpedantic)
if(LUXEL_WERROR)
  target_compile_options(luxel_warnings INTERFACE -Werror)
endif()

add_library(luxel_sanitizers INTERFACE)
if(LUXEL_SANITIZE)
  target_compile_options(luxel_sanitizers INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                    -fno-sanitize-recover=undefined)
  target_link_options(luxel_sanitizers INTERFACE -fsanitize=address,undefined)
  # GCC 12's flow analysis, with the sanitizers' instrumentation, reports std::regex and
  # std::function internals as "maybe uninitialized": a known false positive that -Werror would
  # turn into a failed build.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(luxel_sanitizers INTERFACE -Wno-maybe-uninitialized)
  endif()
endif()

# Common settings for every luxel target. Build-tree only: the installed libraries do not make
# their users compile with luxel's warnings or sanitizers.
function(luxel_target_defaults target)
  target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:luxel_warnings>)
  target_link_libraries(${target} PUBLIC $<BUILD_INTERFACE:luxel_sanitizers>)
endfunction()
