# Compiles GLSL compute shaders to SPIR-V with glslc at build time and embeds them in a generated
# C++ source (uint32_t arrays + a name -> words registry), so no shader files are needed at run time.
#
# luxel_embed_shaders(TARGET <library> SHADERS <file.comp.glsl>... DEPENDS <headers>...)
function(luxel_embed_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "SHADERS;DEPENDS" ${ARGN})
  set(spv_dir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
  file(MAKE_DIRECTORY ${spv_dir})
  set(spv_files)
  foreach(shader ${ARG_SHADERS})
    get_filename_component(name ${shader} NAME)
    string(REPLACE ".comp.glsl" "" name ${name})
    set(spv ${spv_dir}/${name}.spv)
    add_custom_command(
      OUTPUT ${spv}
      COMMAND ${GLSLC_EXECUTABLE} -fshader-stage=compute --target-env=vulkan1.3 -O
              -I ${PROJECT_SOURCE_DIR}/src/gpu/shaders -o ${spv} ${shader}
      DEPENDS ${shader} ${ARG_DEPENDS}
      COMMENT "glslc ${name}"
      VERBATIM)
    list(APPEND spv_files ${spv})
  endforeach()
  set(generated ${CMAKE_CURRENT_BINARY_DIR}/shader_registry_data.cpp)
  add_custom_command(
    OUTPUT ${generated}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${generated} "-DSPIRV_FILES=${spv_files}"
            -P ${PROJECT_SOURCE_DIR}/cmake/SpirvToCpp.cmake
    DEPENDS ${spv_files} ${PROJECT_SOURCE_DIR}/cmake/SpirvToCpp.cmake
    COMMENT "embedding SPIR-V"
    VERBATIM)
  target_sources(${ARG_TARGET} PRIVATE ${generated})
endfunction()
