#include "client/render/hull_renderer.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "client/render/frustum.hpp"
#include "client/render/gl_program.hpp"
#include "client/render/hull_mesh.hpp"
#include "client/render/renderer.hpp"
#include "client/render/shader_sources.hpp"

namespace ocean::render {
namespace {

bool sphere_visible(const Frustum& frustum, const glm::vec3& centre, float radius) {
  for (const Plane& p : frustum.planes())
    if (glm::dot(p.normal, centre) + p.offset < -radius) return false;
  return true;
}

}  // namespace

HullLight hull_light(const Renderer& renderer) {
  const glm::vec3 horizon = renderer.horizon_colour();
  return {renderer.desc().sun_direction, renderer.sun_colour(), horizon, horizon, renderer.fog()};
}

bool HullRenderer::init(std::string& error) {
  shutdown();
  program_ = build_program("hull", shader_source::hull_vert, shader_source::hull_frag,
                           {{0, "a_pos"}, {1, "a_normal"}, {2, "a_colour"}}, error);
  if (!program_) return false;
  u_clip_from_rel_ = glGetUniformLocation(program_, "u_clip_from_rel");
  u_rotation_ = glGetUniformLocation(program_, "u_rotation");
  u_offset_ = glGetUniformLocation(program_, "u_offset");
  u_sun_dir_ = glGetUniformLocation(program_, "u_sun_dir");
  u_sun_colour_ = glGetUniformLocation(program_, "u_sun_colour");
  u_sky_light_ = glGetUniformLocation(program_, "u_sky_light");
  u_fog_colour_ = glGetUniformLocation(program_, "u_fog_colour");
  u_fog_ = glGetUniformLocation(program_, "u_fog");
  return true;
}

const HullRenderer::Buffers& HullRenderer::buffers_for(const HullInstance& hull) {
  Buffers& b = meshes_[{hull.length_m, hull.beam_m, hull.draft_m}];
  b.used = true;
  if (b.vertices) return b;
  const HullMesh mesh = hull_mesh(hull.length_m, hull.beam_m, hull.draft_m);
  glGenBuffers(1, &b.vertices);
  glBindBuffer(GL_ARRAY_BUFFER, b.vertices);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(HullVertex)), mesh.vertices.data(),
               GL_STATIC_DRAW);
  glGenBuffers(1, &b.indices);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint16_t)), mesh.indices.data(),
               GL_STATIC_DRAW);
  b.count = static_cast<GLsizei>(mesh.indices.size());
  b.radius_m = mesh.radius_m;
  return b;
}

const std::vector<std::size_t>& HullRenderer::draw(const Camera& camera, int width, int height,
                                                   const std::vector<HullInstance>& hulls, const HullLight& light) {
  drawn_.clear();
  if (!program_ || hulls.empty() || width <= 0 || height <= 0) return drawn_;
  const glm::mat4 clip_from_rel = camera.clip_from_relative(static_cast<float>(width) / static_cast<float>(height));
  const Frustum frustum = Frustum::from_clip_matrix(clip_from_rel);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_BLEND);
  glUseProgram(program_);
  glUniformMatrix4fv(u_clip_from_rel_, 1, GL_FALSE, glm::value_ptr(clip_from_rel));
  glUniform3fv(u_sun_dir_, 1, glm::value_ptr(light.sun_direction));
  glUniform3fv(u_sun_colour_, 1, glm::value_ptr(light.sun_colour));
  glUniform3fv(u_sky_light_, 1, glm::value_ptr(light.sky_light));
  glUniform3fv(u_fog_colour_, 1, glm::value_ptr(light.fog_colour));
  glUniform2fv(u_fog_, 1, glm::value_ptr(light.fog));
  for (auto& [size, b] : meshes_) b.used = false;
  for (GLuint slot = 0; slot < 3; ++slot) glEnableVertexAttribArray(slot);
  const Buffers* bound = nullptr;
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    const HullInstance& hull = hulls[i];
    const Buffers& b = buffers_for(hull);
    const glm::vec3 offset(hull.position - camera.position);
    if (!sphere_visible(frustum, offset, b.radius_m)) continue;
    glUniformMatrix3fv(u_rotation_, 1, GL_FALSE, glm::value_ptr(hull.rotation));
    glUniform3fv(u_offset_, 1, glm::value_ptr(offset));
    if (bound != &b) {  // hulls of one size share their buffers (a fleet of a few designs)
      bound = &b;
      glBindBuffer(GL_ARRAY_BUFFER, b.vertices);
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.indices);
      const auto stride = static_cast<GLsizei>(sizeof(HullVertex));
      const auto at = [](std::size_t offset) { return reinterpret_cast<const void*>(offset); };
      glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(HullVertex, position)));
      glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(HullVertex, normal)));
      glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(HullVertex, colour)));
    }
    glDrawElements(GL_TRIANGLES, b.count, GL_UNSIGNED_SHORT, nullptr);
    drawn_.push_back(i);
  }
  for (GLuint slot = 0; slot < 3; ++slot) glDisableVertexAttribArray(slot);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  // Sizes no vessel has any more give their buffers back.
  for (auto it = meshes_.begin(); it != meshes_.end();) {
    if (it->second.used) {
      ++it;
      continue;
    }
    glDeleteBuffers(1, &it->second.vertices);
    glDeleteBuffers(1, &it->second.indices);
    it = meshes_.erase(it);
  }
  return drawn_;
}

void HullRenderer::shutdown() {
  for (auto& [size, b] : meshes_) {
    glDeleteBuffers(1, &b.vertices);
    glDeleteBuffers(1, &b.indices);
  }
  meshes_.clear();
  if (program_) glDeleteProgram(program_);
  program_ = 0;
}

}  // namespace ocean::render
