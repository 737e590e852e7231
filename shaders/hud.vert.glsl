#version 100
// HUD text quads from stb_easy_font, in window pixels with y down.
attribute vec2 a_pos;
attribute vec4 a_colour;
uniform vec2 u_pixel_to_ndc;  // 2 / width, 2 / height
varying vec4 v_colour;

void main() {
  v_colour = a_colour;
  gl_Position = vec4(a_pos.x * u_pixel_to_ndc.x - 1.0, 1.0 - a_pos.y * u_pixel_to_ndc.y, 0.0, 1.0);
}
