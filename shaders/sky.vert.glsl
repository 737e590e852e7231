#version 100
// Skybox as one full-screen triangle on the far plane; each corner carries its view ray.
attribute vec2 a_ndc;
uniform mat4 u_rel_from_clip;  // inverse of the camera-relative clip matrix, scaled to ~unit rays
varying vec3 v_dir;

void main() {
  vec4 p = u_rel_from_clip * vec4(a_ndc, 1.0, 1.0);
  v_dir = p.xyz / p.w;
  gl_Position = vec4(a_ndc, 1.0, 1.0);
}
