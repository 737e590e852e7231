// What the water's shader is told each frame: the light (sun, sky, weather, glitter, glow), the
// foam, the fog and horizon, the coarse cascade's and wake's textures and the nearest foam trails.
#include "client/render/renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "client/render/weather_light.hpp"

namespace ocean::render {

glm::vec3 Renderer::horizon_colour() const {
  glm::vec3 sum(0.0f);
  for (const glm::vec3& c : weathered_ring_) sum += c;
  return weathered_ring_.empty() ? glm::vec3(0.6f) : sum / static_cast<float>(weathered_ring_.size());
}

void Renderer::set_ocean_uniforms(const Camera& camera, const glm::mat4& clip_from_rel) {
  const OceanProgram& program = ocean_program();
  const OceanUniforms& u = program.u;
  glUseProgram(program.id);
  glUniformMatrix4fv(u.clip_from_rel, 1, GL_FALSE, glm::value_ptr(clip_from_rel));
  glUniform1f(u.eye_height, static_cast<float>(camera.position.y));
  glUniform1f(u.choppiness, desc_.choppiness);
  glUniform1f(u.detail_fade, 2.0f / desc_.view_distance_m);
  glUniform1f(u.far_roughness, 0.35f);
  glUniform4f(u.foam, whitecaps_ ? whitecaps_->threshold : desc_.foam_threshold, 1.0f / (whitecaps_ ? whitecaps_->band : kFoamBand),
              whitecaps_ ? whitecaps_->cover : 0.0f, whitecaps_ ? 1.0f : 0.0f);
  glUniform1f(u.foam_only, desc_.foam_only ? 1.0f : 0.0f);
  if (whitecaps_) {
    // The eye along and across the wind, modulo the lace's period there (ocean.frag.glsl: 256
    // lattice cells at 0.4 and 1.6 cells a metre): the lace stays put however far the eye goes.
    const double wx = whitecaps_->wind_x, wz = whitecaps_->wind_z;
    const auto wrap = [](double v, double period) { return static_cast<float>(v - period * std::floor(v / period)); };
    glUniform2f(u.lace, whitecaps_->wind_x, whitecaps_->wind_z);
    glUniform2f(u.lace_eye, wrap(camera.position.x * wx + camera.position.z * wz, 640.0),
                wrap(camera.position.z * wx - camera.position.x * wz, 160.0));
  }
  glUniform1i(u.sky, 0);
  glUniform3fv(u.sun_dir, 1, glm::value_ptr(desc_.sun_direction));
  // Under a cloud deck the sun barely shows and the water turns a darker grey-green.
  const glm::vec3 sun = sun_colour();
  const glm::vec3 deep = desc_.deep_colour * (1.0f - 0.3f * overcast_);
  const glm::vec3 scatter = desc_.scatter_colour * (1.0f - 0.3f * overcast_);
  glUniform3fv(u.sun_colour, 1, glm::value_ptr(sun));
  glUniform3fv(u.deep_colour, 1, glm::value_ptr(deep));
  glUniform3fv(u.scatter_colour, 1, glm::value_ptr(scatter));
  glUniform4f(u.overcast, kOvercastDeck.r, kOvercastDeck.g, kOvercastDeck.b, overcast_);
  glUniform1f(u.shininess, desc_.shininess);
  const GlitterLobe glitter = glitter_for_wind(wind_mps_, desc_.shininess);
  glUniform2f(u.glitter, glitter.exponent, glitter.weight);
  glUniform3fv(u.glow, 1, glm::value_ptr(sun * desc_.glow_colour));
  glUniform2fv(u.fog, 1, glm::value_ptr(fog()));
  glUniform3f(u.foam_colour, 0.92f, 0.95f, 0.97f);
  glUniform3fv(u.horizon, static_cast<GLsizei>(weathered_ring_.size()), glm::value_ptr(weathered_ring_[0]));
  if (coarse_.active()) {
    coarse_.bind(GL_TEXTURE1);
    glUniform1i(u.coarse_shape, 1);
    glUniform1i(u.coarse_chop, 2);
    glUniform3f(u.coarse_scale, 1.0f / coarse_.patch_x(), 1.0f / coarse_.patch_z(), static_cast<float>(coarse_.n()));
  }
  set_trail_uniforms(camera);
  if (wake_.active()) {
    wake_.bind(GL_TEXTURE3);
    glUniform1i(u.wake_shape, 3);
    glUniform1i(u.wake_chop, 4);
    glUniform3f(u.wake_scale, 1.0f / wake_.patch_x(), 1.0f / wake_.patch_z(), static_cast<float>(wake_.n()));
  }
}

void Renderer::set_trail_uniforms(const Camera& camera) {
  const OceanUniforms& u = ocean_program().u;
  // The nearest kMaxTrails of those with foam, by their squared distance from the eye.
  std::array<std::pair<double, const FoamTrail*>, 32> near{};  // a fleet has at most 32 tracks (PROTOCOL.md 8)
  std::size_t count = 0;
  for (const FoamTrail& t : trails_)
    if (t.strength > 0.0f && t.length_m > 0.0f && count < near.size()) {
      const double dx = t.stern_x_m - camera.position.x, dz = t.stern_z_m - camera.position.z;
      near[count++] = {dx * dx + dz * dz, &t};
    }
  const std::size_t kept = std::min(count, kMaxTrails);
  std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(kept), near.begin() + static_cast<std::ptrdiff_t>(count),
                    [](const auto& a, const auto& b) { return a.first < b.first; });
  std::array<glm::vec4, 2 * kMaxTrails> packed{};
  for (std::size_t i = 0; i < kept; ++i) {
    const FoamTrail& t = *near[i].second;
    packed[2 * i] = {static_cast<float>(t.stern_x_m - camera.position.x), static_cast<float>(t.stern_z_m - camera.position.z),
                     -t.dir_x * t.length_m, -t.dir_z * t.length_m};
    packed[2 * i + 1] = {t.half_width_m, t.spread, t.strength, 0.0f};
  }
  glUniform4fv(u.trail, static_cast<GLsizei>(packed.size()), glm::value_ptr(packed[0]));
  glUniform1f(u.trails, static_cast<float>(kept));
  glUniform2f(u.eye_xz, static_cast<float>(std::fmod(camera.position.x, 1024.0)),
              static_cast<float>(std::fmod(camera.position.z, 1024.0)));
}

}  // namespace ocean::render
