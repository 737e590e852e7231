#version 100
// Hulls lit like the scene: the sun (dimmed under a cloud deck), the sky's light from above, a
// little bounce from the water, and the water's distance fog towards the horizon's colour.
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
#else
precision mediump float;
#endif

uniform vec3 u_sun_dir;     // unit, toward the sun
uniform vec3 u_sun_colour;  // already dimmed by the overcast
uniform vec3 u_sky_light;   // the sky's light from straight above
uniform vec3 u_fog_colour;
uniform vec2 u_fog;         // the water's: density per metre, normaliser (full at the view distance)
varying vec3 v_normal;
varying vec3 v_colour;
varying vec3 v_rel;

void main() {
  vec3 n = normalize(v_normal);
  float sun = max(dot(n, u_sun_dir), 0.0);
  vec3 ambient = u_sky_light * (0.55 + 0.45 * n.y) + vec3(0.02, 0.05, 0.06) * max(-n.y, 0.0);
  vec3 lit = v_colour * (ambient + 0.45 * u_sun_colour * sun);
  float fog = min((1.0 - exp(-u_fog.x * length(v_rel.xz))) * u_fog.y, 1.0);
  gl_FragColor = vec4(mix(lit, u_fog_colour, fog), 1.0);
}
