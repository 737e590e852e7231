// The GLES 2 ocean renderer: one static patch grid (uploaded once) tiled to the horizon, per-frame
// attribute streams (height, slopes, optional choppy displacement and Jacobian), a sky cube map.
// No windowing and no networking: the caller owns the context and the frame data.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <GLES2/gl2.h>
#include <glm/glm.hpp>

#include "client/render/camera.hpp"
#include "client/render/coarse_cascade.hpp"
#include "client/render/patch_buffers.hpp"
#include "client/render/tile_selection.hpp"
#include "client/render/whitecap_cover.hpp"

namespace ocean::render {

// Zero (or null) in any field means "the default" written beside it.
struct RendererDesc {
  const char* sky_dir = nullptr;      // folder with px.png .. nz.png; null: default_sky_dirs()
  float view_distance_m = 0.0f;       // 2500: tiles are drawn out to here
  float lod0_distance_m = 0.0f;       // half a patch width: full-detail radius; +1 level per doubling
  int max_lod_level = 0;              // 5 (stride 32), reduced to what the grid size allows
  int chunks_per_side = 0;            // 2 (1 for grids under 16): LOD granularity within a tile
  int far_block_tiles = 0;            // about view distance / 5 patches (1 = off): tiles per far draw
  float choppiness = 0.0f;            // 1: scale applied to the streamed displacement
  float foam_threshold = 0.0f;        // 0.75: foam where the Jacobian is below this, full 0.2 lower (without set_whitecaps)
  glm::vec3 sun_direction{0.0f};      // estimated from the sky's brightest spot
  glm::vec3 sun_colour{0.0f};         // the sunlight at the sun's elevation (sun_light.hpp)
  glm::vec3 deep_colour{0.0f};        // (0.01, 0.06, 0.10)
  glm::vec3 scatter_colour{0.0f};     // (0.02, 0.12, 0.11)
  glm::vec3 glow_colour{0.0f};        // (0.05, 0.24, 0.20): what of the sunlight a thin crest lets through
  float shininess = 0.0f;             // 600: Phong exponent of the sun highlight
  float fog_density = 0.0f;           // 3.2 / view distance, per metre; the fog is full at the view distance
  // Leave the coarse cascade undrawn even where the GL could: what a GL without vertex texture
  // fetch shows (tests), or a GL whose vertex texture reads are too slow.
  bool without_coarse_cascade = false;
  // Draw the water's foam term alone: red the foam (0..1), green 1 on water, black where no water
  // is (no sky): what a test measures the foam's share of the water with.
  bool foam_only = false;
  // Draw the foam without its lace (smooth patches): what a GL without highp fragment floats shows
  // (tests).
  bool without_foam_lace = false;
};

// One frame of samples, each n x n floats, row-major with rows along +z (index row * n + col).
// height is required; null slopes are derived from the heights by central differences;
// null displacement means none and a null Jacobian means 1 (no foam).
struct FrameStreams {
  const float* height = nullptr;
  const float* slope_x = nullptr;
  const float* slope_z = nullptr;
  const float* disp_x = nullptr;
  const float* disp_z = nullptr;
  const float* jacobian = nullptr;
};

// The churned water behind a moving hull (drawn as foam from its pose alone, no wire data):
// from the stern backwards along -heading for length_m, half_width_m wide at the stern and
// widening by spread per metre behind it, strength in [0, 1].
struct FoamTrail {
  double stern_x_m = 0.0, stern_z_m = 0.0;
  float dir_x = 1.0f, dir_z = 0.0f;  // the hull's heading (unit)
  float length_m = 0.0f, half_width_m = 0.0f, spread = 0.0f, strength = 0.0f;
};

struct DrawStats {
  int tiles_drawn = 0;    // tiles and chunks drawn (a far block counts all its tiles)
  int far_blocks = 0;     // of which drawn as far blocks
  int tiles_culled = 0;   // chunks in range but outside the view
  int draw_calls = 0;
  std::int64_t triangles = 0;
  std::array<int, 6> tiles_per_level{};  // levels above 5 are counted as 5
};

class Renderer {
 public:
  Renderer() = default;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  ~Renderer() { shutdown(); }

  // Needs a current GLES 2 context. Compiles the shaders and loads the sky.
  bool init(const RendererDesc& desc);
  // The patch is n x n samples spanning patch_x_m x patch_z_m metres; builds the static grid VBO
  // and the LOD index buffers. Call again when the stream's grid changes.
  bool set_grid(int n, float patch_x_m, float patch_z_m);
  // A coarse cascade (common/cascade.hpp): a larger lattice of the same sea, n x n samples over
  // patch_x_m x patch_z_m, added at every vertex to the tile, which then carries only the short
  // waves; the sum repeats every coarse patch instead of every tile. Needs vertex texture fetch
  // and float textures (coarse_cascade_supported(), after init); n = 0 removes it.
  bool coarse_cascade_supported() const { return programs_[1].id != 0; }
  const std::string& coarse_cascade_unsupported() const { return coarse_unsupported_; }  // why not
  bool set_coarse_grid(int n, float patch_x_m, float patch_z_m);
  // Why the foam is drawn without its lace (empty where it has it); init says so on stderr too.
  const std::string& foam_lace_unsupported() const { return lace_unsupported_; }
  bool has_coarse_grid() const { return coarse_.active(); }
  bool upload_coarse_frame(const FrameStreams& frame);

  // The vessels' wake lattice (CODEC.md 7.9): n x n samples over a size_m square whose corner is
  // at (origin_x_m, origin_z_m), added where it lies and nowhere else. Needs the GL the coarse
  // cascade needs (and two more vertex texture units beside one); n = 0 removes it.
  bool wake_supported() const { return programs_[2].id != 0; }
  bool set_wake_grid(int n, float size_m, float origin_x_m, float origin_z_m);
  bool has_wake_grid() const { return wake_.active(); }
  bool upload_wake_frame(const FrameStreams& frame);
  // The weather's light (weather_light.hpp): 0 a clear sky .. 1 all cloud deck, which hides the
  // sun and greys the sky, its reflection and the water.
  void set_overcast(float overcast);
  float overcast() const { return overcast_; }
  // The wind over the sea (m/s): the rougher the sea, the broader the sun's glitter.
  void set_wind_speed(float wind_mps) { wind_mps_ = wind_mps; }
  // The sun's colour under the weather: a cloud deck lets a tenth of it through.
  glm::vec3 sun_colour() const { return desc_.sun_colour * (1.0f - 0.9f * overcast_); }
  // The distance fog of a point d metres away horizontally: min((1 - exp(-x d)) y, 1), normalised
  // to be full at the view distance, where the tiles end: (x, y).
  glm::vec2 fog() const {
    return {desc_.fog_density, 1.0f / (1.0f - std::exp(-desc_.fog_density * desc_.view_distance_m))};
  }
  // The sky's colour just above the horizon, averaged round it, under the weather: what the water
  // fades into with distance, and the light the sky sheds on things above the water.
  glm::vec3 horizon_colour() const;
  // With whitecaps (Whitecaps::shade), the tile's Jacobian stream carries its foam (0..1), the
  // coarse cascade's and the wake's own folds foam below J 0.75, the far field shows the cover and
  // the foam is drawn as lace; without, foam is the tile's Jacobian below desc().foam_threshold,
  // none far off.
  void set_whitecaps(std::optional<WhitecapShading> shading) { whitecaps_ = shading; }
  // The foam trails of this frame (the nearest kMaxTrails to the camera are drawn).
  static constexpr std::size_t kMaxTrails = 8;
  void set_trails(std::span<const FoamTrail> trails) { trails_.assign(trails.begin(), trails.end()); }
  // Uploads only the attribute streams of one frame (sizes from set_grid).
  bool upload_frame(const FrameStreams& frame);
  bool upload_frame(const float* height, const float* slope_x, const float* slope_z,
                    const float* disp_x = nullptr, const float* disp_z = nullptr, const float* jacobian = nullptr);
  // Draws into the bound framebuffer's (0, 0, width, height) viewport; clears colour and depth.
  void draw(const Camera& camera, int width, int height, double time_s);
  void shutdown();

  const std::string& error() const { return error_; }
  const DrawStats& last_stats() const { return stats_; }
  const RendererDesc& desc() const { return desc_; }  // with defaults filled in
  int grid_n() const { return n_; }

 private:
  bool fail(std::string reason);
  bool build_ocean_programs(const RendererDesc& in);
  bool load_sky_and_sun(const RendererDesc& in);
  void release_grid();
  void build_tile_indices(int n, int chunk_cells, bool wide);
  void build_far_blocks(int n, float patch_x_m, float patch_z_m, bool wide);
  // draw()'s steps: which tiles the camera sees, the water's uniforms, the water, then the sky.
  TileSelection visible_tiles(const Camera& camera, const glm::mat4& clip_from_rel) const;
  void set_ocean_uniforms(const Camera& camera, const glm::mat4& clip_from_rel);
  void draw_tiles(const TileSelection& tiles);
  void draw_sky(const Camera& camera, const glm::mat4& clip_from_rel);
  void set_trail_uniforms(const Camera& camera);

  RendererDesc desc_;
  std::string error_;
  bool ready_ = false;

  struct OceanUniforms {
    GLint clip_from_rel, tile_offset, eye_height, choppiness, detail_fade, far_roughness, foam;
    GLint sky, sun_dir, sun_colour, deep_colour, scatter_colour, shininess, glitter, glow, fog, foam_colour, horizon, overcast;
    GLint coarse_shape, coarse_chop, coarse_scale, coarse_origin;  // -1 in the plain program
    GLint wake_shape, wake_chop, wake_scale, wake_origin;          // -1 without the wake
    GLint trail, trails, eye_xz, foam_only, lace, lace_eye;
  };
  struct OceanProgram {
    GLuint id = 0;
    OceanUniforms u{};
  };
  bool build_ocean_program(OceanProgram& program, bool coarse, bool wake, bool lace = false);
  // plain, coarse, wake, coarse + wake, then each with the foam's lace (id 0 where this GL cannot
  // build it); laced for a stream's whitecaps where it could be built.
  const OceanProgram& ocean_program() const {
    const int base = (coarse_.active() ? 1 : 0) + (wake_.active() ? 2 : 0);
    return programs_[whitecaps_ && programs_[base + 4].id ? base + 4 : base];
  }
  // Where a tile starting at tile index (ix, iz) lies in the coarse patch, in [0, 1).
  glm::vec2 coarse_origin(int ix, int iz) const;
  // Where a tile starting at tile index (ix, iz) lies from the wake square's corner, metres.
  glm::vec2 wake_origin(int ix, int iz) const;

  OceanProgram programs_[8];  // by ocean_program()'s index; all but the plain one optional
  std::string coarse_unsupported_;                // why not, where it does not
  std::string lace_unsupported_;                  // why the foam has no lace, where it has none
  CoarseCascade coarse_;
  CoarseCascade wake_;  // the vessels' wake lattice, the same two textures
  float wake_origin_x_ = 0.0f, wake_origin_z_ = 0.0f;
  GLuint sky_program_ = 0;
  GLuint sky_texture_ = 0, sky_triangle_ = 0;
  PatchBuffers tile_;  // one patch: every LOD level and stitch variant
  PatchBuffers far_;   // far_span_^2 patches at the coarsest level, one draw per far block

  struct IndexRange {
    std::size_t byte_offset = 0;
    GLsizei count = 0;
  };
  // [((chunk + 1) * (lod_levels_ + 1) + level) * kEdgeMaskCount + coarser_edges]; chunk -1 = whole tile
  std::vector<IndexRange> index_ranges_;
  int chunks_per_side_ = 1;
  int far_span_ = 1;
  GLsizei far_index_count_ = 0;
  GLenum far_index_type_ = GL_UNSIGNED_SHORT;
  GLenum index_type_ = GL_UNSIGNED_SHORT;
  int n_ = 0, lod_levels_ = 0;
  float patch_x_ = 0.0f, patch_z_ = 0.0f;

  bool has_frame_ = false;
  StreamsPresent present_{};  // the streams the last frame gave
  float max_height_ = 0.0f, max_disp_ = 0.0f;
  std::vector<glm::vec3> horizon_ring_;
  std::vector<float> scratch_, scratch_slope_x_, scratch_slope_z_;

  GLint sky_u_rel_from_clip_ = -1, sky_u_sky_ = -1, sky_u_overcast_ = -1;
  float overcast_ = 0.0f;
  float wind_mps_ = 0.0f;
  std::vector<FoamTrail> trails_;
  std::optional<WhitecapShading> whitecaps_;
  std::vector<glm::vec3> weathered_ring_;

  DrawStats stats_;
};

}  // namespace ocean::render
