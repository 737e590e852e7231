#include "client/render/hud_overlay.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include <stb_easy_font.h>

#include "client/render/gl_program.hpp"
#include "client/render/shader_sources.hpp"

namespace ocean::render {

namespace {

constexpr int kMaxQuads = 4096;   // index buffer capacity; ~40 lines of text
constexpr std::size_t kVertexBytes = 16;  // x, y, z floats + RGBA8, stb_easy_font's layout

void append_quad(std::vector<char>& out, float x0, float y0, float x1, float y1, const unsigned char rgba[4]) {
  const float corners[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  std::size_t at = out.size();
  out.resize(at + 4 * kVertexBytes);
  for (const auto& c : corners) {
    const float xyz[3] = {c[0], c[1], 0.0f};
    std::memcpy(&out[at], xyz, 12);
    std::memcpy(&out[at + 12], rgba, 4);
    at += kVertexBytes;
  }
}

}  // namespace

bool HudOverlay::init(std::string& error) {
  shutdown();
  program_ = build_program("hud", shader_source::hud_vert, shader_source::hud_frag, {{0, "a_pos"}, {1, "a_colour"}}, error);
  if (!program_) return false;
  u_pixel_to_ndc_ = glGetUniformLocation(program_, "u_pixel_to_ndc");
  std::vector<std::uint16_t> indices;
  indices.reserve(kMaxQuads * 6);
  for (int q = 0; q < kMaxQuads; ++q) {
    const auto b = static_cast<std::uint16_t>(q * 4);
    indices.insert(indices.end(), {b, static_cast<std::uint16_t>(b + 1), static_cast<std::uint16_t>(b + 2), b,
                                   static_cast<std::uint16_t>(b + 2), static_cast<std::uint16_t>(b + 3)});
  }
  glGenBuffers(1, &index_buffer_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * 2), indices.data(), GL_STATIC_DRAW);
  glGenBuffers(1, &vertex_buffer_);
  return true;
}

void HudOverlay::draw(const HudStats& s, int width, int height) {
  if (!program_ || width <= 0 || height <= 0) return;
  char text[1024];
  std::snprintf(text, sizeof text, "fps %.1f\nkbps %.1f\nlatency %.1f ms\nloss %.2f %%\nprofile %s%s%s%s%s", s.fps,
                s.kbps, s.latency_ms, s.loss_percent, s.profile.empty() ? "-" : s.profile.c_str(),
                s.extra.empty() ? "" : "\n", s.extra.c_str(), s.vessels.empty() ? "" : "\n", s.vessels.c_str());

  text_vertices_.clear();
  const unsigned char backing[4] = {0, 0, 0, 140};
  const float w = static_cast<float>(stb_easy_font_width(text)), h = static_cast<float>(stb_easy_font_height(text));
  append_quad(text_vertices_, 2.0f, 2.0f, w + 8.0f, h + 6.0f, backing);
  const std::size_t before = text_vertices_.size();
  text_vertices_.resize(before + kMaxQuads * 4 * kVertexBytes);
  unsigned char white[4] = {255, 255, 255, 255};
  const int quads = stb_easy_font_print(5.0f, 5.0f, text, white, text_vertices_.data() + before,
                                        static_cast<int>(text_vertices_.size() - before));
  text_vertices_.resize(before + static_cast<std::size_t>(quads) * 4 * kVertexBytes);
  const int total_quads = std::min(quads + 1, kMaxQuads);

  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glUseProgram(program_);
  // stb_easy_font glyphs are ~7 px high: doubled on large viewports to stay readable.
  const float scale = height >= 480 ? 2.0f : 1.0f;
  glUniform2f(u_pixel_to_ndc_, 2.0f * scale / width, 2.0f * scale / height);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(text_vertices_.size()), text_vertices_.data(), GL_STREAM_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, kVertexBytes, nullptr);
  glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, kVertexBytes, reinterpret_cast<const void*>(12));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
  glDrawElements(GL_TRIANGLES, total_quads * 6, GL_UNSIGNED_SHORT, nullptr);
  glDisableVertexAttribArray(0);
  glDisableVertexAttribArray(1);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

void HudOverlay::shutdown() {
  if (program_) glDeleteProgram(program_);
  if (vertex_buffer_) glDeleteBuffers(1, &vertex_buffer_);
  if (index_buffer_) glDeleteBuffers(1, &index_buffer_);
  program_ = vertex_buffer_ = index_buffer_ = 0;
}

}  // namespace ocean::render
