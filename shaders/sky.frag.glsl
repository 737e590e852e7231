#version 100
// Skybox: the generated cube map looked up along the view ray.
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
#else
precision mediump float;
#endif
uniform samplerCube u_sky;
varying vec3 v_dir;

void main() {
  // Below the horizon only the ocean's far edge can show: paint it the horizon haze the water
  // fades into (the colour the ocean shader's horizon ring samples, 0.01 rad up).
  vec3 d = v_dir;
  d.y = max(d.y, 0.01 * length(d.xz));
  gl_FragColor = vec4(textureCube(u_sky, d).rgb, 1.0);
}
