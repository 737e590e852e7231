// The heads-up display: a few lines of stats drawn with stb_easy_font over the scene. The caller
// fills HudStats (the network layer knows kbps, latency and loss); this only draws them.
#pragma once

#include <string>
#include <vector>

#include <GLES2/gl2.h>

namespace ocean::render {

struct HudStats {
  double fps = 0.0;
  double kbps = 0.0;            // received payload rate
  double latency_ms = 0.0;      // frame age when shown
  double loss_percent = 0.0;
  std::string profile;          // stream profile name, e.g. "mobile"
  std::string extra;            // optional free text (one line), e.g. tiles drawn
  std::string vessels;          // optional lines: the vessels in view, e.g. "vessel 3 7.0 m/s (following)"
};

class HudOverlay {
 public:
  HudOverlay() = default;
  HudOverlay(const HudOverlay&) = delete;
  HudOverlay& operator=(const HudOverlay&) = delete;
  ~HudOverlay() { shutdown(); }

  bool init(std::string& error);  // needs a current context
  // Draws in the top-left corner of a width x height viewport, alpha-blended, no depth test.
  void draw(const HudStats& stats, int width, int height);
  void shutdown();

 private:
  GLuint program_ = 0, vertex_buffer_ = 0, index_buffer_ = 0;
  GLint u_pixel_to_ndc_ = -1;
  std::vector<char> text_vertices_;  // stb_easy_font output, 16 bytes per vertex
};

}  // namespace ocean::render
