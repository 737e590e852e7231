#version 100
// Ocean surface fragment stage: per-fragment light from the streamed slopes - a Schlick-weighted
// sky reflection, the sun's glitter, deep-water colour with a little scatter and the sun's light
// through thin crests - then foam and distance fog.
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
#else
precision mediump float;
#endif

uniform samplerCube u_sky;
uniform vec3 u_sun_dir;        // unit, toward the sun
uniform vec3 u_sun_colour;
uniform vec3 u_deep_colour;
uniform vec3 u_scatter_colour;
uniform float u_shininess;     // the resolved facets' sharp highlight
uniform vec2 u_glitter;        // the unresolved ripples' broad lobe: its exponent and weight
uniform vec3 u_glow;           // the sun's light through a crest (its colour after the water's absorption)
uniform vec3 u_foam_colour;
uniform vec4 u_overcast;       // as in sky.frag.glsl: the reflection shows the same sky
uniform float u_foam_only;     // 1: the foam term alone (RendererDesc::foam_only)
uniform vec2 u_lace;           // the wind's unit direction (x, z): the foam's lace is drawn out along it
uniform vec2 u_lace_eye;       // the eye along and across the wind, modulo the lace's period (640, 160 m)

varying vec3 v_rel;
varying vec2 v_slope;
varying vec2 v_foam;     // the sea's whitecaps, the hulls' churned water and wake crests
varying float v_height;
varying vec4 v_haze;

vec3 weathered(vec3 c) {
  return mix(c, u_overcast.rgb * (0.6 + 0.4 * dot(c, vec3(0.3, 0.5, 0.2))), u_overcast.a);
}

#ifdef FOAM_LACE
// Periodic over 256 lattice cells, so the lace repeats every 640 m along the wind and 160 m across
// (its 0.4 and 1.6 cells a metre): the eye's offset taken modulo that never makes it jump.
float hash(vec2 c) {
  c = mod(c, 256.0);
  return fract(sin(dot(c, vec2(12.9898, 78.233))) * 43758.5453);
}

float value_noise(vec2 p) {
  vec2 i = floor(p);
  vec2 f = fract(p);
  f = f * f * (3.0 - 2.0 * f);
  return mix(mix(hash(i), hash(i + vec2(1.0, 0.0)), f.x), mix(hash(i + vec2(0.0, 1.0)), hash(i + vec2(1.0, 1.0)), f.x), f.y);
}

// Foam up close is lace, not a magnified sample: the interpolated cover is redistributed by a
// noise drawn out along the wind (streaks), keeping its mean - full foam and none stay as they are.
// Built with FOAM_LACE, the program a stream's whitecaps are drawn with: llvmpipe does not skip a
// branch on a uniform, so a calm stream's program leaves it out.
float laced(float foam) {
  if (foam <= 0.0 || foam >= 1.0) return foam;
  vec2 q = vec2(dot(v_rel.xz, u_lace.xy), dot(v_rel.xz, vec2(-u_lace.y, u_lace.x))) + u_lace_eye;
  float n = clamp((value_noise(q * vec2(0.4, 1.6)) - 0.5) * 2.5, -1.0, 1.0);
  return foam + n * min(foam, 1.0 - foam);
}
#else
float laced(float foam) { return foam; }
#endif

void main() {
  vec3 n = normalize(vec3(-v_slope.x, 1.0, -v_slope.y));
  vec3 view = normalize(v_rel);             // eye toward the surface
  vec3 r = reflect(view, n);
  r.y = abs(r.y);                            // a reflection never shows the sky below the horizon
  float facing = max(dot(n, -view), 0.0);
  float m = 1.0 - facing;                    // Schlick, (1 - cos)^5 without pow
  float m2 = m * m;
  float fresnel = 0.02 + 0.98 * m2 * m2 * m;

  vec3 sky = weathered(textureCube(u_sky, r).rgb);
  float lit = max(dot(n, u_sun_dir), 0.0);
  float crest = clamp(0.35 + 0.25 * v_height, 0.0, 1.0);
  vec3 water = u_deep_colour * (0.4 + 0.6 * lit) + u_scatter_colour * crest * (1.0 - facing);
  // A crest standing between the eye and a low sun lets its light through where it is thin: a
  // green-blue glow (the water has taken the red), the more the more the eye looks into the sun.
  float into_sun = max(dot(view, u_sun_dir), 0.0);
  into_sun *= into_sun;
  water += u_glow * (into_sun * into_sun) * clamp(0.4 * v_height, 0.0, 1.0);
  vec3 colour = mix(water, sky, fresnel);
  // The glitter: the facets the grid resolves flash sharply; the ripples it cannot resolve (the
  // rougher, the more wind) spread the sun into a broad path toward it.
  float toward = log2(max(dot(r, u_sun_dir), 1e-4));  // both lobes' powers from one logarithm
  colour += u_sun_colour * (exp2(u_shininess * toward) + u_glitter.y * exp2(u_glitter.x * toward)) * (0.3 + fresnel);
  float foam = max(laced(v_foam.x), v_foam.y);  // a hull's churn has its own grain
  colour = mix(colour, u_foam_colour * (0.8 + 0.2 * lit), foam);

  // Toward the horizon the water turns into the sky colour just above it, hiding the tiling.
  gl_FragColor = vec4(mix(colour, v_haze.rgb, v_haze.a), 1.0);
  if (u_foam_only > 0.5) gl_FragColor = vec4(foam, 1.0, 0.0, 1.0);
}
