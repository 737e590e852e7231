# Writes a C++ header holding each GLSL file as a string constant, so the programs need no shader
# files at run time. Usage: cmake -DOUTPUT=<header> -DSOURCES=<a.glsl|b.glsl> -P embed_shaders.cmake
# ocean.vert.glsl becomes ocean::render::shader_source::ocean_vert.
set(text "// Generated from shaders/*.glsl by client/render/embed_shaders.cmake; edit the .glsl files.\n#pragma once\n\nnamespace ocean::render::shader_source {\n")
string(REPLACE "|" ";" sources "${SOURCES}")
foreach(src IN LISTS sources)
  get_filename_component(name ${src} NAME)
  string(REGEX REPLACE "\\.glsl$" "" name ${name})
  string(REPLACE "." "_" name ${name})
  file(READ ${src} body)
  string(APPEND text "\ninline constexpr const char ${name}[] = R\"glsl(${body})glsl\";\n")
endforeach()
string(APPEND text "\n}  // namespace ocean::render::shader_source\n")
file(WRITE ${OUTPUT}.tmp "${text}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
