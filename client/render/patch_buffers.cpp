#include "client/render/patch_buffers.hpp"

namespace ocean::render {

void PatchBuffers::create() {
  destroy();
  GLuint names[6];
  glGenBuffers(6, names);
  positions = names[0];
  indices = names[1];
  height = names[2];
  slope = names[3];
  displacement = names[4];
  jacobian = names[5];
}

void PatchBuffers::destroy() {
  const GLuint names[6] = {positions, indices, height, slope, displacement, jacobian};
  for (GLuint b : names)
    if (b) glDeleteBuffers(1, &b);
  *this = {};
}

void PatchBuffers::bind(bool has_displacement, bool has_jacobian) const {
  const auto stream = [](GLuint location, GLuint buffer, GLint components) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(location);
  };
  stream(kGrid, positions, 2);
  stream(kHeight, height, 1);
  stream(kSlope, slope, 2);
  if (has_displacement) {
    stream(kDisp, displacement, 2);
  } else {
    glDisableVertexAttribArray(kDisp);
    glVertexAttrib2f(kDisp, 0.0f, 0.0f);
  }
  if (has_jacobian) {
    stream(kJacobian, jacobian, 1);
  } else {
    glDisableVertexAttribArray(kJacobian);
    glVertexAttrib1f(kJacobian, 1.0f);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
}

void PatchBuffers::unbind() {
  for (GLuint a : {kGrid, kHeight, kSlope, kDisp, kJacobian}) glDisableVertexAttribArray(a);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void upload_static(GLuint buffer, const std::vector<float>& data) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
}

void upload_stream(GLuint buffer, const std::vector<float>& data) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STREAM_DRAW);
}

void upload_indices(GLuint buffer, const std::vector<std::uint32_t>& indices, bool wide) {
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
  if (wide) {
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * 4), indices.data(), GL_STATIC_DRAW);
  } else {
    const std::vector<std::uint16_t> narrow(indices.begin(), indices.end());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(narrow.size() * 2), narrow.data(), GL_STATIC_DRAW);
  }
}

}  // namespace ocean::render
