#version 100
// HUD: flat vertex colour (text and its translucent backing).
precision mediump float;
varying vec4 v_colour;

void main() {
  gl_FragColor = v_colour;
}
