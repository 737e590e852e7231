// Compiling and linking GLSL ES programs with their attribute slots fixed before linking;
// failures return 0 and put the GL info log, labelled with the shader's name, in error.
#pragma once

#include <initializer_list>
#include <span>
#include <string>

#include <GLES2/gl2.h>

namespace ocean::render {

struct AttributeSlot {
  GLuint location;
  const char* name;
};

// Whether the context's GL_EXTENSIONS string names `name`.
bool has_extension(const char* name);

GLuint build_program(const char* label, const char* vertex_source, const char* fragment_source,
                     std::initializer_list<AttributeSlot> attributes, std::string& error);
GLuint build_program(const char* label, const char* vertex_source, const char* fragment_source,
                     std::span<const AttributeSlot> attributes, std::string& error);

}  // namespace ocean::render
