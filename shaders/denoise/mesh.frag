#version 330 core
// Denoising lab, fragment stage. Flat shading from screen-space derivatives of the position: the
// face normal of exactly the triangle drawn, so noise shows as facets and smoothing as their
// absence, whatever normals the mesh carries. The heat views colour a per-vertex scalar:
//   VIEW_HEAT    0 .. u_heatScale mean edge lengths (error to the clean mesh, or the seam gap)
//   VIEW_SIGNED  -2 .. +2 u_heatScale (the offset along the normal: blue in, red out)
#include "common/output.glsl"

uniform vec3 u_eye;
uniform vec3 u_keyDir;  // towards the key light: above and to the left of the camera, whatever the orbit
uniform float u_heatScale;
// 0: the surface; 1: a ghost (dimmed, bluish: the input behind a result that collapsed); 2: a
// marker (orange: the point the mesh collapsed to, drawn as points).
uniform int u_style;

in vec3 v_world;
in float v_heat;
out vec4 o_color;

// A perceptually ordered ramp: slate, purple, orange, pale yellow (after "inferno", starting at a
// slate that stays readable against the dark background where the value is 0).
vec3 heatRamp(float t) {
  t = clamp(t, 0.0, 1.0);
  vec3 a = mix(vec3(0.33, 0.36, 0.45), vec3(0.5, 0.12, 0.45), smoothstep(0.0, 0.4, t));
  vec3 b = mix(a, vec3(0.93, 0.41, 0.14), smoothstep(0.35, 0.75, t));
  return mix(b, vec3(0.99, 1.0, 0.64), smoothstep(0.7, 1.0, t));
}

vec3 signedRamp(float t) {
  t = clamp(t, -1.0, 1.0);
  return t < 0.0 ? mix(vec3(0.92), vec3(0.15, 0.35, 0.85), -t) : mix(vec3(0.92), vec3(0.85, 0.2, 0.15), t);
}

void main() {
  if (u_style == 2) {
    o_color = vec4(1.0, 0.55, 0.1, 1.0);
    return;
  }
  vec3 n = cross(dFdx(v_world), dFdy(v_world));
  float len = length(n);
  n = len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
  vec3 v = normalize(u_eye - v_world);
  if (dot(n, v) < 0.0) n = -n;  // both sides lit: open meshes show their inside
#if defined(VIEW_HEAT)
  vec3 albedo = heatRamp(v_heat / max(u_heatScale, 1e-9));
#elif defined(VIEW_SIGNED)
  vec3 albedo = signedRamp(v_heat / max(2.0 * u_heatScale, 1e-9));
#else
  vec3 albedo = vec3(0.78, 0.76, 0.72);
#endif
  // A key light from the camera's upper left and a dim headlight: facets read from any side, and
  // the key's grazing angle makes small bumps (noise) cast visible shade.
  float light = 0.06 + 0.8 * max(dot(n, u_keyDir), 0.0) + 0.22 * max(dot(n, v), 0.0);
  vec3 h = normalize(u_keyDir + v);
  float gloss = 0.12 * pow(max(dot(n, h), 0.0), 40.0);
  vec3 lit = albedo * light + vec3(gloss);
  if (u_style == 1) lit = mix(vec3(0.05, 0.07, 0.11), vec3(0.25, 0.32, 0.45) * light, 0.6);
  o_color = encodeOutput(lit);
  o_color.a = 1.0;
}
