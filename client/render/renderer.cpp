#include "client/render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <GLES2/gl2ext.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "client/render/gl_program.hpp"
#include "client/render/grid_mesh.hpp"
#include "client/render/lod.hpp"
#include "client/render/weather_light.hpp"
#include "client/render/periodic_field.hpp"
#include "client/render/shader_sources.hpp"
#include "client/render/sky_faces.hpp"
#include "client/render/sky_texture.hpp"
#include "client/render/sun_light.hpp"
#include "client/render/tile_selection.hpp"

namespace ocean::render {

namespace {

template <typename T>
T or_default(T value, T fallback) {
  return value == T{} ? fallback : value;
}

}  // namespace

bool Renderer::build_ocean_program(OceanProgram& program, bool coarse, bool wake, bool lace) {
  namespace src = shader_source;
  std::string vertex = src::ocean_vert, fragment = src::ocean_frag;
  // The defines go right after the "#version 100" line, which must stay first.
  if (wake) vertex.insert(vertex.find('\n') + 1, "#define WAKE_LATTICE\n");
  if (coarse) vertex.insert(vertex.find('\n') + 1, "#define COARSE_CASCADE\n");
  if (lace) fragment.insert(fragment.find('\n') + 1, "#define FOAM_LACE\n");
  const std::string name = std::string("ocean") + (coarse ? " (coarse cascade)" : "") + (wake ? " (wake)" : "") +
                           (lace ? " (lace)" : "");
  std::array<AttributeSlot, 1 + kOceanStreamCount> slots{{{kGrid, "a_grid"}}};
  for (std::size_t i = 0; i < kOceanStreamCount; ++i) slots[1 + i] = {kOceanStreams[i].slot, kOceanStreams[i].name};
  program.id = build_program(name.c_str(), vertex.c_str(), fragment.c_str(), slots, error_);
  if (!program.id) return false;
  const auto loc = [&](const char* name) { return glGetUniformLocation(program.id, name); };
  program.u = {loc("u_clip_from_rel"), loc("u_tile_offset"), loc("u_eye_height"), loc("u_choppiness"),
               loc("u_detail_fade"), loc("u_far_roughness"), loc("u_foam"), loc("u_sky"),
               loc("u_sun_dir"), loc("u_sun_colour"), loc("u_deep_colour"), loc("u_scatter_colour"),
               loc("u_shininess"), loc("u_glitter"), loc("u_glow"), loc("u_fog"), loc("u_foam_colour"), loc("u_horizon[0]"), loc("u_overcast"),
               loc("u_coarse_shape"), loc("u_coarse_chop"), loc("u_coarse_scale"), loc("u_coarse_origin"),
               loc("u_wake_shape"), loc("u_wake_chop"), loc("u_wake_scale"), loc("u_wake_origin"),
               loc("u_trail[0]"), loc("u_trails"), loc("u_eye_xz"), loc("u_foam_only"), loc("u_lace"), loc("u_lace_eye")};
  return true;
}

bool Renderer::fail(std::string reason) {
  error_ = std::move(reason);
  return false;
}

// The plain program, then the variants this GL can build (coarse cascade, wake, each laced): a GL
// that cannot build one still draws what the others can, and says what it lacks.
bool Renderer::build_ocean_programs(const RendererDesc& in) {
  if (!build_ocean_program(programs_[0], false, false)) return false;
  // The coarse and wake variants are optional: a GL that cannot build them still draws the tile.
  coarse_unsupported_ = in.without_coarse_cascade
                            ? "RendererDesc::without_coarse_cascade"
                            : "this GL has no vertex texture fetch (2 units) or no GL_OES_texture_float";
  if (!in.without_coarse_cascade && CoarseCascade::supported()) {
    GLint units = 0;
    glGetIntegerv(GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS, &units);
    if (build_ocean_program(programs_[1], true, false)) coarse_unsupported_.clear();
    else coarse_unsupported_ = error_;
    (void)build_ocean_program(programs_[2], false, true);
    if (units >= 4) (void)build_ocean_program(programs_[3], true, true);
    error_.clear();
  }
  // Each with the foam's lace too (a choppy stream's whitecaps): a fragment noise that costs
  // llvmpipe about a sixth of a frame, so a calm stream's program goes without it. Its hash needs
  // highp: at mediump it would draw stripes, so such a GL draws the foam as smooth patches.
  GLint range[2] = {0, 0}, precision = 0;
  glGetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT, range, &precision);
  lace_unsupported_ = in.without_foam_lace ? "RendererDesc::without_foam_lace"
                      : precision == 0     ? "this GL has no highp float in fragment shaders"
                                           : "";
  for (int i = 0; i < 4 && lace_unsupported_.empty(); ++i)
    if (programs_[i].id && !build_ocean_program(programs_[i + 4], i & 1, i & 2, true)) lace_unsupported_ = error_;
  if (!lace_unsupported_.empty()) {
    for (int i = 4; i < 8; ++i) {  // every variant laced or none: never a mix by GL
      if (programs_[i].id) glDeleteProgram(programs_[i].id);
      programs_[i] = {};
    }
    std::fprintf(stderr, "ocean renderer: warning: the foam is drawn without its lace, as smooth patches (%s)\n",
                 lace_unsupported_.c_str());
  }
  return true;
}

// The sky's program and texture, and what the water takes from the sky: the sun (its direction,
// and its colour from its elevation unless the desc sets one) and the horizon's haze.
bool Renderer::load_sky_and_sun(const RendererDesc& in) {
  namespace src = shader_source;
  sky_program_ = build_program("sky", src::sky_vert, src::sky_frag, {{0, "a_ndc"}}, error_);
  if (!sky_program_) return false;

  sky_u_rel_from_clip_ = glGetUniformLocation(sky_program_, "u_rel_from_clip");
  sky_u_sky_ = glGetUniformLocation(sky_program_, "u_sky");
  sky_u_overcast_ = glGetUniformLocation(sky_program_, "u_overcast");

  SkyFaces faces;
  if (!load_sky(in.sky_dir, faces, error_)) return false;
  if (desc_.sun_direction == glm::vec3(0.0f)) desc_.sun_direction = estimate_sun_direction(faces);
  desc_.sun_direction = glm::normalize(desc_.sun_direction);
  desc_.sun_colour = or_default(in.sun_colour, sunlight(std::asin(std::clamp(desc_.sun_direction.y, -1.0f, 1.0f))));
  const auto ring = horizon_ring(faces, 0.01f);  // matches the sky shader's below-horizon colour
  horizon_ring_.assign(ring.begin(), ring.end());
  set_overcast(overcast_);  // the haze the ocean fades into, under the weather set so far
  sky_texture_ = create_sky_texture(faces);

  return true;
}

bool Renderer::init(const RendererDesc& in) {
  shutdown();
  if (!glGetString(GL_VERSION)) return fail("Renderer::init needs a current GLES 2 context (glGetString returned null)");
  desc_ = in;
  desc_.view_distance_m = or_default(in.view_distance_m, 2500.0f);
  desc_.max_lod_level = or_default(in.max_lod_level, 5);
  desc_.chunks_per_side = or_default(in.chunks_per_side, 2);
  desc_.far_block_tiles = std::max(0, in.far_block_tiles);  // resolved per patch size in set_grid
  desc_.choppiness = or_default(in.choppiness, 1.0f);
  // Foam where the surface compresses, from J 0.75, full at 0.55, until a frame's whitecaps are
  // set (WhitecapCover: the threshold that covers the share observed at the wind).
  desc_.foam_threshold = or_default(in.foam_threshold, 0.75f);
  desc_.deep_colour = or_default(in.deep_colour, glm::vec3(0.01f, 0.06f, 0.10f));
  desc_.scatter_colour = or_default(in.scatter_colour, glm::vec3(0.02f, 0.12f, 0.11f));
  desc_.glow_colour = or_default(in.glow_colour, glm::vec3(0.05f, 0.24f, 0.20f));
  desc_.shininess = or_default(in.shininess, 600.0f);
  desc_.fog_density = or_default(in.fog_density, 3.2f / desc_.view_distance_m);
  if (desc_.view_distance_m < 0.0f || desc_.lod0_distance_m < 0.0f || desc_.max_lod_level < 0)
    return fail("RendererDesc: view_distance_m, lod0_distance_m and max_lod_level must be >= 0");
  if (desc_.chunks_per_side < 1 || desc_.chunks_per_side > 8)
    return fail("RendererDesc: chunks_per_side must be 1..8, got " + std::to_string(desc_.chunks_per_side));

  if (!build_ocean_programs(in)) return false;
  error_.clear();
  if (!load_sky_and_sun(in)) return false;
  desc_.sky_dir = nullptr;  // read: the caller's string need not outlive init

  const float triangle[] = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};
  glGenBuffers(1, &sky_triangle_);
  glBindBuffer(GL_ARRAY_BUFFER, sky_triangle_);
  glBufferData(GL_ARRAY_BUFFER, sizeof triangle, triangle, GL_STATIC_DRAW);
  if (const GLenum e = glGetError(); e != GL_NO_ERROR) return fail("GL error " + std::to_string(e) + " while creating renderer resources");
  ready_ = true;
  return true;
}

bool Renderer::upload_frame(const float* height, const float* slope_x, const float* slope_z,
                            const float* disp_x, const float* disp_z, const float* jacobian) {
  return upload_frame(FrameStreams{height, slope_x, slope_z, disp_x, disp_z, jacobian});
}

bool Renderer::upload_frame(const FrameStreams& f) {
  if (n_ == 0) return fail("Renderer::upload_frame called before set_grid");
  if (!f.height) return fail("upload_frame: FrameStreams::height is required");
  if ((f.disp_x == nullptr) != (f.disp_z == nullptr))
    return fail("upload_frame: give both disp_x and disp_z, or neither");
  const int n = n_;
  const std::size_t count = static_cast<std::size_t>(n) * n;

  float max_h = 0.0f;
  for (std::size_t i = 0; i < count; ++i) max_h = std::max(max_h, std::abs(f.height[i]));
  max_height_ = max_h;
  const auto [sx, sz] = slopes_or_differences(n, patch_x_, patch_z_, f.height, f.slope_x, f.slope_z, scratch_slope_x_,
                                              scratch_slope_z_);
  const bool has_disp = f.disp_x != nullptr;
  max_disp_ = 0.0f;
  if (has_disp) {
    float max_d2 = 0.0f;
    for (std::size_t i = 0; i < count; ++i) max_d2 = std::max(max_d2, f.disp_x[i] * f.disp_x[i] + f.disp_z[i] * f.disp_z[i]);
    max_disp_ = std::sqrt(max_d2) * desc_.choppiness;
  }

  // The tile mesh takes every sample; the far block every coarsest-stride sample, repeated.
  const auto stream = [&](OceanAttribute a, std::initializer_list<const float*> fields) {
    present_[a - kHeight] = fields.begin()[0] != nullptr;
    if (!present_[a - kHeight]) return;
    expand_periodic(n, fields, scratch_);
    upload_stream(tile_.stream(a), scratch_);
    if (far_span_ > 1) {
      expand_periodic_strided(n, 1 << lod_levels_, far_span_, fields, scratch_);
      upload_stream(far_.stream(a), scratch_);
    }
  };
  stream(kHeight, {f.height});
  stream(kSlope, {sx, sz});
  stream(kDisp, {f.disp_x, f.disp_z});
  stream(kJacobian, {f.jacobian});
  has_frame_ = true;
  return true;
}

bool Renderer::set_coarse_grid(int n, float patch_x_m, float patch_z_m) {
  if (!ready_) return fail("Renderer::set_coarse_grid called before a successful init");
  coarse_.destroy();
  if (n == 0) return true;
  if (!coarse_cascade_supported()) return fail("set_coarse_grid: " + coarse_unsupported_);
  return coarse_.create(n, patch_x_m, patch_z_m, error_);
}

bool Renderer::upload_coarse_frame(const FrameStreams& frame) { return coarse_.upload(frame, error_); }

bool Renderer::set_wake_grid(int n, float size_m, float origin_x_m, float origin_z_m) {
  if (!ready_) return fail("Renderer::set_wake_grid called before a successful init");
  wake_.destroy();
  if (n == 0) return true;
  if (!wake_supported()) return fail("set_wake_grid: " + coarse_unsupported_);
  wake_origin_x_ = origin_x_m;
  wake_origin_z_ = origin_z_m;
  return wake_.create(n, size_m, size_m, error_);
}

bool Renderer::upload_wake_frame(const FrameStreams& frame) { return wake_.upload(frame, error_); }

glm::vec2 Renderer::wake_origin(int ix, int iz) const {
  return {static_cast<float>(static_cast<double>(ix) * patch_x_ - wake_origin_x_),
          static_cast<float>(static_cast<double>(iz) * patch_z_ - wake_origin_z_)};
}

glm::vec2 Renderer::coarse_origin(int ix, int iz) const {
  // In double: tile indices times the patch reach millions of metres far from the origin.
  const auto place = [](int index, float patch, float coarse) {
    const double at = static_cast<double>(index) * patch / coarse;
    return static_cast<float>(at - std::floor(at));
  };
  return {place(ix, patch_x_, coarse_.patch_x()), place(iz, patch_z_, coarse_.patch_z())};
}

void Renderer::set_overcast(float overcast) {
  overcast_ = overcast;
  weathered_ring_.resize(horizon_ring_.size());
  for (std::size_t i = 0; i < horizon_ring_.size(); ++i) weathered_ring_[i] = weathered(horizon_ring_[i], overcast_);
}

void Renderer::draw(const Camera& camera, int width, int height, double /*time_s: the streams carry time*/) {
  stats_ = {};
  glViewport(0, 0, width, height);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (!ready_ || width <= 0 || height <= 0) return;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);

  const glm::mat4 clip_from_rel = camera.clip_from_relative(static_cast<float>(width) / static_cast<float>(height));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, sky_texture_);
  if (has_frame_) {
    const TileSelection tiles = visible_tiles(camera, clip_from_rel);
    set_ocean_uniforms(camera, clip_from_rel);
    draw_tiles(tiles);
  }
  // The sky last, on the far plane, so it only shades pixels no water covered.
  if (!desc_.foam_only) draw_sky(camera, clip_from_rel);
}

TileSelection Renderer::visible_tiles(const Camera& camera, const glm::mat4& clip_from_rel) const {
  TileSelectionInput sel;
  sel.camera_position = camera.position;
  sel.clip_from_relative = clip_from_rel;
  sel.patch_x_m = patch_x_;
  sel.patch_z_m = patch_z_;
  sel.view_distance_m = desc_.view_distance_m;
  sel.max_height_m = max_height_ + coarse_.max_height() + wake_.max_height();
  sel.max_displacement_m = max_disp_ + (coarse_.max_displacement() + wake_.max_displacement()) * desc_.choppiness;
  sel.lod.lod0_distance_m = desc_.lod0_distance_m > 0.0f ? desc_.lod0_distance_m : 0.5f * std::max(patch_x_, patch_z_);
  sel.lod.max_level = lod_levels_;
  sel.chunks_per_side = chunks_per_side_;
  sel.far_block_tiles = far_span_;
  return select_tiles(sel);
}

void Renderer::draw_tiles(const TileSelection& tiles) {
  // Tiles and chunks first (nearest first), then the far blocks with their own buffers.
  const OceanUniforms& u = ocean_program().u;
  const bool coarse = coarse_.active(), wake = wake_.active();
  tile_.bind(present_);
  for (const TileDraw& t : tiles.draws) {
    if (t.span > 1) continue;
    const IndexRange& range = index_ranges_[((t.chunk + 1) * (lod_levels_ + 1) + t.level) * kEdgeMaskCount + t.coarser_edges];
    glUniform2f(u.tile_offset, t.offset_relative.x, t.offset_relative.y);
    if (coarse) glUniform2fv(u.coarse_origin, 1, glm::value_ptr(coarse_origin(t.ix, t.iz)));
    if (wake) glUniform2fv(u.wake_origin, 1, glm::value_ptr(wake_origin(t.ix, t.iz)));
    glDrawElements(GL_TRIANGLES, range.count, index_type_, reinterpret_cast<const void*>(range.byte_offset));
    stats_.triangles += range.count / 3;
    ++stats_.tiles_per_level[std::min(t.level, 5)];
    ++stats_.tiles_drawn;
    ++stats_.draw_calls;
  }
  bool far_bound = false;
  for (const TileDraw& t : tiles.draws) {
    if (t.span == 1) continue;
    if (!far_bound) far_.bind(present_);
    far_bound = true;
    glUniform2f(u.tile_offset, t.offset_relative.x, t.offset_relative.y);
    if (coarse) glUniform2fv(u.coarse_origin, 1, glm::value_ptr(coarse_origin(t.ix, t.iz)));
    if (wake) glUniform2fv(u.wake_origin, 1, glm::value_ptr(wake_origin(t.ix, t.iz)));
    glDrawElements(GL_TRIANGLES, far_index_count_, far_index_type_, nullptr);
    stats_.triangles += far_index_count_ / 3;
    stats_.tiles_per_level[std::min(t.level, 5)] += t.span * t.span;
    stats_.tiles_drawn += t.span * t.span;
    ++stats_.far_blocks;
    ++stats_.draw_calls;
  }
  stats_.tiles_culled = tiles.culled;
  PatchBuffers::unbind();
}

void Renderer::draw_sky(const Camera& camera, const glm::mat4& clip_from_rel) {
  glUseProgram(sky_program_);
  // Rays scaled from far-plane length (thousands of metres) to about 1: squaring them in a
  // mediump (fp16) fragment stage would overflow.
  const glm::mat4 rel_from_clip = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / camera.far_m)) * glm::inverse(clip_from_rel);
  glUniformMatrix4fv(sky_u_rel_from_clip_, 1, GL_FALSE, glm::value_ptr(rel_from_clip));
  glUniform1i(sky_u_sky_, 0);
  glUniform4f(sky_u_overcast_, kOvercastDeck.r, kOvercastDeck.g, kOvercastDeck.b, overcast_);
  glBindBuffer(GL_ARRAY_BUFFER, sky_triangle_);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisableVertexAttribArray(0);
  ++stats_.draw_calls;
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void Renderer::shutdown() {
  if (!ready_ && !programs_[0].id && !sky_program_) return;
  release_grid();
  coarse_.destroy();
  wake_.destroy();
  for (OceanProgram& p : programs_) {
    if (p.id) glDeleteProgram(p.id);
    p = {};
  }
  if (sky_program_) glDeleteProgram(sky_program_);
  if (sky_texture_) glDeleteTextures(1, &sky_texture_);
  if (sky_triangle_) glDeleteBuffers(1, &sky_triangle_);
  sky_program_ = sky_texture_ = sky_triangle_ = 0;
  ready_ = false;
}

}  // namespace ocean::render
