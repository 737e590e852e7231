#version 100
// Ocean surface vertex stage: the static patch grid (a_grid) displaced by the per-frame streams.
// Positions are camera-relative so tiles far from the origin keep float precision.
// Built with COARSE_CASCADE defined, it adds a coarse cascade (a larger lattice of the same sea,
// common/cascade.hpp) sampled from textures at the vertex's place in that lattice, so that the
// sum repeats only every coarse patch. Built with WAKE_LATTICE defined, it adds the vessels' wake
// (CODEC.md 7.9): a lattice over one square of the world, sampled where the vertex lies inside it
// and nothing outside, so a wake is cast once.

attribute vec2 a_grid;       // metres inside the patch (static VBO)
attribute float a_height;    // metres (streamed)
attribute vec2 a_slope;      // dh/dx, dh/dz (streamed)
attribute vec2 a_disp;       // choppy horizontal displacement, metres (streamed or constant 0)
attribute float a_jacobian;  // horizontal Jacobian, < 1 where the surface folds (streamed or 1); the foam (0..1) when u_foam.w is 1

uniform mat4 u_clip_from_rel;
uniform vec2 u_tile_offset;   // tile origin minus eye position, x and z
uniform float u_eye_height;
uniform float u_choppiness;
uniform float u_detail_fade;  // 1 / distance where slopes have faded to u_far_roughness
uniform float u_far_roughness;
uniform vec4 u_foam;          // threshold, 1 / softness, the mean foam (far off), 1: a_jacobian is the tile's foam (Whitecaps)
uniform vec2 u_fog;           // density per metre, 1 / (1 - exp(-density * view distance))
uniform vec3 u_horizon[16];   // sky colour 0.01 rad above the horizon, azimuth 2 pi (i / 16 - 0.5)
// The turbulent foam behind each moving hull (at most 8, the nearest), from its pose alone:
// [2i] = stern minus eye (x, z), the trail's whole length backwards along -heading (x, z);
// [2i + 1] = half width at the stern, widening per metre behind, strength (0 = none), unused.
uniform vec4 u_trail[16];
uniform float u_trails;       // how many of them are set
uniform vec2 u_eye_xz;        // the eye's world x, z modulo 1024 m: the foam's grain stays put
#if defined(COARSE_CASCADE) || defined(WAKE_LATTICE)
// Bilinear between the four nearest of n x n samples: float textures need not filter (GLES 2).
vec4 lattice_sample(sampler2D field, vec2 uv, float n) {
  vec2 t = uv * n - 0.5;
  vec2 f = fract(t);
  vec2 a = (floor(t) + 0.5) / n;
  vec2 b = a + 1.0 / n;
  vec4 lo = mix(texture2D(field, a), texture2D(field, vec2(b.x, a.y)), f.x);
  vec4 hi = mix(texture2D(field, vec2(a.x, b.y)), texture2D(field, b), f.x);
  return mix(lo, hi, f.y);
}
#endif
#ifdef COARSE_CASCADE
uniform sampler2D u_coarse_shape;  // height, dh/dx, dh/dz, 0 per coarse sample (nearest, repeat)
uniform sampler2D u_coarse_chop;   // displacement x, z, J - 1, 0 per coarse sample
uniform vec3 u_coarse_scale;       // 1 / coarse patch x, 1 / coarse patch z, samples per side
uniform vec2 u_coarse_origin;      // the tile origin's place in the coarse patch, in [0, 1)
#endif
#ifdef WAKE_LATTICE
uniform sampler2D u_wake_shape;    // as the coarse cascade's, of the wake lattice
uniform sampler2D u_wake_chop;
uniform vec3 u_wake_scale;         // 1 / wake size (twice), samples per side
uniform vec2 u_wake_origin;        // the tile origin minus the wake square's corner, metres
#endif

varying vec3 v_rel;      // surface point minus eye
varying vec2 v_slope;    // slopes, flattened with distance to keep far tiles from sparkling
varying vec2 v_foam;     // the sea's whitecaps, the hulls' churned water and wake crests
varying float v_height;
varying vec4 v_haze;     // horizon colour in this direction, fog amount

// The foam of the trails at a camera-relative point: white at the stern, fading and widening
// behind it, broken into patches by a hash of the place (churned water is not uniform).
float trail_foam(vec2 xz) {
  float foam = 0.0;
  for (int i = 0; i < 8; ++i) {
    if (float(i) >= u_trails) break;
    vec4 a = u_trail[2 * i];
    vec4 b = u_trail[2 * i + 1];
    vec2 d = xz - a.xy;
    float len2 = max(dot(a.zw, a.zw), 1e-6);
    float s = dot(d, a.zw) / len2;                      // 0 at the stern, 1 at the trail's end
    float across = length(d - s * a.zw);
    float half_width = b.x + b.y * s * sqrt(len2);
    float along = step(0.0, s) * step(s, 1.0) * (1.0 - s) * (1.0 - s);
    float edge = clamp((half_width - across) / max(0.35 * half_width, 0.01), 0.0, 1.0);
    foam = max(foam, b.z * along * edge);
  }
  if (foam <= 0.0) return 0.0;
  // 0.75 cells a metre: the eye's 1024 m wrap is a whole number of cells, so the grain never jumps.
  vec2 cell = floor((xz + u_eye_xz) * 0.75);
  float grain = fract(sin(dot(cell, vec2(12.9898, 78.233))) * 43758.5453);
  return foam * (0.55 + 0.45 * grain);
}

void main() {
  float height = a_height;
  vec2 disp = a_disp;
  vec2 coarse_slope = vec2(0.0);
  float folds = 0.0;  // J - 1 of the coarse cascade and the wake
#ifdef COARSE_CASCADE
  vec2 uv = u_coarse_origin + a_grid * u_coarse_scale.xy;
  vec4 shape = lattice_sample(u_coarse_shape, uv, u_coarse_scale.z);
  vec4 chop = lattice_sample(u_coarse_chop, uv, u_coarse_scale.z);
  height += shape.x;
  coarse_slope = shape.yz;
  disp += chop.xy;
  // First order in the coarse derivatives (a few hundredths for long waves): J0 + (J1 - 1).
  folds += chop.z;
#endif
#ifdef WAKE_LATTICE
  vec2 wuv = (u_wake_origin + a_grid) * u_wake_scale.xy;
  float inside = step(0.0, wuv.x) * step(0.0, wuv.y) * step(wuv.x, 1.0) * step(wuv.y, 1.0);
  vec4 wshape = lattice_sample(u_wake_shape, wuv, u_wake_scale.z) * inside;
  vec4 wchop = lattice_sample(u_wake_chop, wuv, u_wake_scale.z) * inside;
  height += wshape.x;
  coarse_slope += wshape.yz;
  disp += wchop.xy;
  folds += wchop.z;
  // A wake's steep crests carry the foam its hull shed and whiten where they near breaking: from
  // a slope of 0.1 (the Kelvin arms' cusps of a hull at speed), full at 0.3 (a Stokes wave breaks
  // near 0.44), on every profile (the choppy ones fold too, through the Jacobian).
  float wake_foam = clamp((length(wshape.yz) - 0.1) * 5.0, 0.0, 1.0) * 0.8;
#else
  float wake_foam = 0.0;
#endif
  vec2 xz = u_tile_offset + a_grid + u_choppiness * disp;
  vec3 rel = vec3(xz.x, height - u_eye_height, xz.y);
  float detail = mix(1.0, u_far_roughness, clamp(length(xz) * u_detail_fade, 0.0, 1.0));
  v_rel = rel;
  // Only the tile's short waves fade with distance (they would sparkle); the long ones stay.
  v_slope = a_slope * detail + coarse_slope;
  // Far off, where the grid's folds would sparkle between pixels, the whitecaps tend to their
  // mean instead of fading: a gale's far sea stays as white as its near one.
  // With the tile's foam streamed in a_jacobian, the coarse cascade's and the wake's own folds
  // foam from J 0.75 as the tile's did before (the tile's threshold is set for its own folds).
  float whitecap = u_foam.w > 0.5 ? max(a_jacobian, clamp((-0.25 - folds) * 5.0, 0.0, 1.0))
                                   : clamp((u_foam.x - a_jacobian - folds) * u_foam.y, 0.0, 1.0);
  v_foam = vec2(mix(u_foam.z, whitecap, detail), max(wake_foam, trail_foam(xz)) * detail);
  v_height = height;
  // Fog per vertex: smooth over a triangle, and it keeps the fragment stage to one texture fetch.
  // Normalised to reach exactly 1 at the view distance, where the tiles end and the sky below
  // the horizon (drawn in the horizon colour) takes over without a visible edge.
  float ring = (atan(xz.y, xz.x) / 6.2831853 + 0.5) * 16.0;
  float first = floor(ring);
  vec3 horizon = mix(u_horizon[int(mod(first, 16.0))], u_horizon[int(mod(first + 1.0, 16.0))], ring - first);
  v_haze = vec4(horizon, min((1.0 - exp(-length(xz) * u_fog.x)) * u_fog.y, 1.0));
  gl_Position = u_clip_from_rel * vec4(rel, 1.0);
}
