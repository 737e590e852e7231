#include "client/render/gl_program.hpp"

#include <cstring>
#include <vector>

namespace ocean::render {

namespace {

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
  if (is_program) glGetProgramInfoLog(object, length, nullptr, log.data());
  else glGetShaderInfoLog(object, length, nullptr, log.data());
  return std::string(log.data());
}

GLuint compile(GLenum stage, const char* label, const char* source, std::string& error) {
  GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    error = std::string(label) + (stage == GL_VERTEX_SHADER ? " vertex" : " fragment") +
            " shader failed to compile: " + info_log(shader, false);
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

bool has_extension(const char* name) {
  const char* all = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  return all && std::strstr(all, name) != nullptr;
}

GLuint build_program(const char* label, const char* vertex_source, const char* fragment_source,
                     std::initializer_list<AttributeSlot> attributes, std::string& error) {
  return build_program(label, vertex_source, fragment_source, std::span<const AttributeSlot>(attributes.begin(), attributes.size()),
                       error);
}

GLuint build_program(const char* label, const char* vertex_source, const char* fragment_source,
                     std::span<const AttributeSlot> attributes, std::string& error) {
  const GLuint vs = compile(GL_VERTEX_SHADER, label, vertex_source, error);
  if (!vs) return 0;
  const GLuint fs = compile(GL_FRAGMENT_SHADER, label, fragment_source, error);
  if (!fs) {
    glDeleteShader(vs);
    return 0;
  }
  GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  for (const AttributeSlot& a : attributes) glBindAttribLocation(program, a.location, a.name);
  glLinkProgram(program);
  glDeleteShader(vs);  // flagged; freed with the program
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    error = std::string(label) + " program failed to link: " + info_log(program, true);
    glDeleteProgram(program);
    return 0;
  }
  return program;
}

}  // namespace ocean::render
