#version 100
// Ocean surface vertex stage: the static patch grid (a_grid) displaced by the per-frame streams.
// Positions are camera-relative so tiles far from the origin keep float precision.

attribute vec2 a_grid;       // metres inside the patch (static VBO)
attribute float a_height;    // metres (streamed)
attribute vec2 a_slope;      // dh/dx, dh/dz (streamed)
attribute vec2 a_disp;       // choppy horizontal displacement, metres (streamed or constant 0)
attribute float a_jacobian;  // horizontal Jacobian, < 1 where the surface folds (streamed or 1)

uniform mat4 u_clip_from_rel;
uniform vec2 u_tile_offset;   // tile origin minus eye position, x and z
uniform float u_eye_height;
uniform float u_choppiness;
uniform float u_detail_fade;  // 1 / distance where slopes have faded to u_far_roughness
uniform float u_far_roughness;
uniform vec2 u_foam;          // threshold, 1 / softness
uniform vec2 u_fog;           // density per metre, 1 / (1 - exp(-density * view distance))
uniform vec3 u_horizon[16];   // sky colour 0.01 rad above the horizon, azimuth 2 pi (i / 16 - 0.5)

varying vec3 v_rel;      // surface point minus eye
varying vec2 v_slope;    // slopes, flattened with distance to keep far tiles from sparkling
varying float v_foam;
varying float v_height;
varying vec4 v_haze;     // horizon colour in this direction, fog amount

void main() {
  vec2 xz = u_tile_offset + a_grid + u_choppiness * a_disp;
  vec3 rel = vec3(xz.x, a_height - u_eye_height, xz.y);
  float detail = mix(1.0, u_far_roughness, clamp(length(xz) * u_detail_fade, 0.0, 1.0));
  v_rel = rel;
  v_slope = a_slope * detail;
  v_foam = clamp((u_foam.x - a_jacobian) * u_foam.y, 0.0, 1.0) * detail;
  v_height = a_height;
  // Fog per vertex: smooth over a triangle, and it keeps the fragment stage to one texture fetch.
  // Normalised to reach exactly 1 at the view distance, where the tiles end and the sky below
  // the horizon (drawn in the horizon colour) takes over without a visible edge.
  float ring = (atan(xz.y, xz.x) / 6.2831853 + 0.5) * 16.0;
  float first = floor(ring);
  vec3 horizon = mix(u_horizon[int(mod(first, 16.0))], u_horizon[int(mod(first + 1.0, 16.0))], ring - first);
  v_haze = vec4(horizon, min((1.0 - exp(-length(xz) * u_fog.x)) * u_fog.y, 1.0));
  gl_Position = u_clip_from_rel * vec4(rel, 1.0);
}
