#version 100
// Vessel hulls: flat-shaded faces placed by the hull's pose, camera-relative like the water.
attribute vec3 a_pos;
attribute vec3 a_normal;
attribute vec3 a_colour;
uniform mat4 u_clip_from_rel;
uniform mat3 u_rotation;    // hull-local to world axes (heading, pitch, roll)
uniform vec3 u_offset;      // the hull's origin minus the camera's position
varying vec3 v_normal;
varying vec3 v_colour;
varying vec3 v_rel;

void main() {
  v_rel = u_rotation * a_pos + u_offset;
  v_normal = u_rotation * a_normal;
  v_colour = a_colour;
  gl_Position = u_clip_from_rel * vec4(v_rel, 1.0);
}
