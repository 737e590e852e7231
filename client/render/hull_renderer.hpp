// HullRenderer: draws the vessels' hulls (hull_mesh.hpp) where their poses put them, after the
// water, lit by the renderer's sun and sky and fogged like it, culled by their bounding spheres
// as the tiles are by their boxes. One vertex buffer per distinct hull size, kept while in use.
#pragma once

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <GLES2/gl2.h>
#include <glm/glm.hpp>

#include "client/render/camera.hpp"

namespace ocean::render {

struct HullInstance {
  glm::dvec3 position{0.0};          // the hull's origin (on its waterline, amidships), world metres
  glm::mat3 rotation{1.0f};          // hull-local axes (+x bow, +y up, +z starboard) in world axes
  float length_m = 0.0f, beam_m = 0.0f, draft_m = 0.0f;
};

struct HullLight {
  glm::vec3 sun_direction{0.0f, 1.0f, 0.0f};
  glm::vec3 sun_colour{1.0f};
  glm::vec3 sky_light{0.5f};
  glm::vec3 fog_colour{0.6f};
  glm::vec2 fog{0.0f, 1.0f};  // as the water's (Renderer::fog): density per metre, normaliser
};

class Renderer;
// The light of the renderer's scene (its sun, its sky under the weather, its fog).
HullLight hull_light(const Renderer& renderer);

class HullRenderer {
 public:
  HullRenderer() = default;
  HullRenderer(const HullRenderer&) = delete;
  HullRenderer& operator=(const HullRenderer&) = delete;
  ~HullRenderer() { shutdown(); }

  bool init(std::string& error);  // needs a current context
  // Into the bound framebuffer over what is there (depth tested against the water); returns the
  // indices of the hulls drawn (the others were outside the view).
  const std::vector<std::size_t>& draw(const Camera& camera, int width, int height, const std::vector<HullInstance>& hulls,
                                       const HullLight& light);
  void shutdown();

 private:
  struct Buffers {
    GLuint vertices = 0, indices = 0;
    GLsizei count = 0;
    float radius_m = 0.0f;
    bool used = false;
  };
  const Buffers& buffers_for(const HullInstance& hull);

  GLuint program_ = 0;
  GLint u_clip_from_rel_ = -1, u_rotation_ = -1, u_offset_ = -1, u_sun_dir_ = -1, u_sun_colour_ = -1;
  GLint u_sky_light_ = -1, u_fog_colour_ = -1, u_fog_ = -1;
  std::map<std::tuple<float, float, float>, Buffers> meshes_;
  std::vector<std::size_t> drawn_;
};

}  // namespace ocean::render
