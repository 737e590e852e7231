#version 100
// Skybox: the generated cube map looked up along the view ray.
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
#else
precision mediump float;
#endif
uniform samplerCube u_sky;
uniform vec4 u_overcast;  // the cloud deck's colour (rgb) and how much of the sky it covers (a)
varying vec3 v_dir;

// The weather's sky: the deck's grey, lit by what it covers (weather_light.cpp's weathered()).
vec3 weathered(vec3 c) {
  return mix(c, u_overcast.rgb * (0.6 + 0.4 * dot(c, vec3(0.3, 0.5, 0.2))), u_overcast.a);
}

void main() {
  // Below the horizon only the ocean's far edge can show: paint it the horizon haze the water
  // fades into (the colour the ocean shader's horizon ring samples, 0.01 rad up).
  vec3 d = v_dir;
  d.y = max(d.y, 0.01 * length(d.xz));
  gl_FragColor = vec4(weathered(textureCube(u_sky, d).rgb), 1.0);
}
