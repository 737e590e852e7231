#include "client/render/patch_buffers.hpp"

namespace ocean::render {

void PatchBuffers::create() {
  destroy();
  GLuint names[2 + kOceanStreamCount];
  glGenBuffers(static_cast<GLsizei>(std::size(names)), names);
  positions = names[0];
  indices = names[1];
  for (std::size_t i = 0; i < kOceanStreamCount; ++i) streams[i] = names[2 + i];
}

void PatchBuffers::destroy() {
  for (GLuint b : {positions, indices})
    if (b) glDeleteBuffers(1, &b);
  for (GLuint b : streams)
    if (b) glDeleteBuffers(1, &b);
  *this = {};
}

void PatchBuffers::bind(const StreamsPresent& present) const {
  const auto stream = [](GLuint location, GLuint buffer, GLint components) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(location);
  };
  stream(kGrid, positions, 2);
  for (std::size_t i = 0; i < kOceanStreamCount; ++i) {
    const OceanStream& s = kOceanStreams[i];
    if (present[i]) {
      stream(s.slot, streams[i], s.components);
      continue;
    }
    glDisableVertexAttribArray(s.slot);
    glVertexAttrib2f(s.slot, s.absent[0], s.absent[1]);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
}

void PatchBuffers::unbind() {
  glDisableVertexAttribArray(kGrid);
  for (const OceanStream& s : kOceanStreams) glDisableVertexAttribArray(s.slot);
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
