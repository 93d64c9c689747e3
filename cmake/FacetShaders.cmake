# Compiles GLSL compute shaders to SPIR-V at build time and embeds them in C++.
#
# facet_add_shaders(TARGET <name> SOURCES a.comp b.comp ...)
# creates an INTERFACE library <name> whose include directory holds one header per
# shader, "<stem>.spv.h", defining `const uint32_t <stem>_spv[]`. glslang writes a
# depfile, so editing an #included file under shaders/lib rebuilds every shader
# that uses it, and a GLSL error fails the build.
function(facet_add_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES" ${ARGN})
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
  file(MAKE_DIRECTORY ${out_dir})
  set(headers)
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(stem ${src} NAME_WE)
    set(abs_src ${CMAKE_CURRENT_SOURCE_DIR}/${src})
    set(header ${out_dir}/${stem}.spv.h)
    add_custom_command(
      OUTPUT ${header}
      COMMAND Vulkan::glslangValidator --target-env vulkan1.2 -I${PROJECT_SOURCE_DIR}/shaders
              --vn ${stem}_spv --depfile ${header}.d -o ${header} ${abs_src}
      DEPENDS ${abs_src}
      DEPFILE ${header}.d
      COMMENT "GLSL -> SPIR-V ${src}"
      VERBATIM)
    list(APPEND headers ${header})
  endforeach()
  add_custom_target(${ARG_TARGET}_spirv DEPENDS ${headers})
  add_library(${ARG_TARGET} INTERFACE)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_spirv)
  target_include_directories(${ARG_TARGET} INTERFACE ${out_dir})
endfunction()
