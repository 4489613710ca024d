#version 330 core
// Shadows lab, camera pass: Blinn-Phong from a key light (directional, spot or point, chosen by
// KEY_TYPE) and an optional spot fill light, each shadowed through its own map; or one of the
// diagnostic views (visibility, bias heat map, texel density, PCSS blocker depth and penumbra).
// Read next: shadow_filters.glsl.
#include "common/output.glsl"
#include "shadows/shadow_filters.glsl"

in vec3 v_worldPos;
in vec3 v_normal;

uniform vec3 u_eye;
uniform vec4 u_baseColor;
uniform float u_ambient;

uniform ShadowLight u_key;
uniform vec3 u_keyPower;   // irradiance at the scene centre x colour (spot/point: x r^2 there)
uniform sampler2D u_keyMap;
uniform samplerCube u_keyCube;
uniform sampler2DShadow u_keyCmp;
uniform samplerCubeShadow u_keyCmpCube;
#ifdef FILL_LIGHT
uniform ShadowLight u_fill;
uniform vec3 u_fillPower;
uniform sampler2D u_fillMap;
uniform sampler2DShadow u_fillCmp;
uniform samplerCube u_noCube;             // the fill light is a spot: never sampled
uniform samplerCubeShadow u_noCmpCube;
#endif

out vec4 o_color;

// Irradiance from a light onto a surface facing N, before shadowing; 0 outside a spot's cone.
vec3 irradiance(int type, ShadowLight L, vec3 power, vec3 P, vec3 N, out float NdotL) {
  vec3 toLight = toLightDir(type, L, P);
  NdotL = dot(N, toLight);
  if (type == LIGHT_DIRECTIONAL) return power;
  float r2 = max(dot(L.position - P, L.position - P), 1e-30);
  float cone = 1.0;
  if (type == LIGHT_SPOT) {
    float cosOuter = cos(atan(L.halfWidth));
    cone = smoothstep(cosOuter, mix(cosOuter, 1.0, 0.1), dot(-toLight, L.axis));
  }
  return power * cone / r2;
}

vec3 blinnPhong(vec3 E, float NdotL, vec3 N, vec3 toLight, vec3 V, vec3 albedo) {
  if (NdotL <= 0.0) return vec3(0.0);
  vec3 H = normalize(toLight + V);
  return E * (albedo * NdotL + 0.25 * pow(max(dot(N, H), 0.0), 48.0));
}

vec3 heatColor(float texels) {
  // Red: shadowed by less than 3 texels (on a lit surface that is acne). Blue: lit by less than
  // 3 texels (where a shadow should begin, that is a leak / peter-panning). Grey: clear cases.
  float t = clamp(abs(texels) / 3.0, 0.0, 1.0);
  vec3 nearZero = texels > 0.0 ? vec3(1.0, 0.1, 0.05) : vec3(0.1, 0.35, 1.0);
  return mix(nearZero, vec3(0.25), t);
}

void main() {
  vec3 N = normalize(gl_FrontFacing ? v_normal : -v_normal);
  vec3 P = v_worldPos;
  vec3 V = normalize(u_eye - P);
  float keyNdotL;
  vec3 keyE = irradiance(KEY_TYPE, u_key, u_keyPower, P, N, keyNdotL);
  bool valid = keyNdotL > 0.0 && max(keyE.r, max(keyE.g, keyE.b)) > 0.0;

  ShadowDebug dbg;
  dbg.heat = 0.0;
  dbg.blocker = -1.0;
  dbg.penumbra = 0.0;
  float keyVis = 1.0;
#ifdef KEY_CASTS
  keyVis = visibility(KEY_TYPE, u_key, u_keyMap, u_keyCube, u_keyCmp, u_keyCmpCube, P, N, dbg);
#endif

#if defined(VIEW_VISIBILITY)
  o_color = vec4(vec3(keyVis), valid ? 1.0 : 0.0);  // data, not a picture: no sRGB encoding
#elif defined(VIEW_POSITION)
  o_color = vec4(P, valid ? 1.0 : 0.0);
#elif defined(VIEW_NORMAL)
  o_color = vec4(N, valid ? 1.0 : 0.0);
#elif defined(VIEW_BIAS_HEAT)
  o_color = encodeOutput(valid ? heatColor(dbg.heat) : vec3(0.05));
#elif defined(VIEW_TEXEL_DENSITY)
  // log2(shadow texel / screen pixel) on the surface: green = matched, red = the map is coarser
  // than the screen (jagged edges), blue = finer (wasted texels).
  float pixelWorld = max(length(fwidth(P)), 1e-30);
  float ratio = log2(max(texelWorldAt(KEY_TYPE, u_key, lightDepth(KEY_TYPE, u_key, P)), 1e-30) / pixelWorld);
  vec3 c = ratio > 0.0 ? mix(vec3(0.2, 0.8, 0.2), vec3(1.0, 0.1, 0.1), clamp(ratio / 3.0, 0.0, 1.0))
                       : mix(vec3(0.2, 0.8, 0.2), vec3(0.1, 0.2, 1.0), clamp(-ratio / 3.0, 0.0, 1.0));
  o_color = encodeOutput(c * (0.35 + 0.65 * max(keyNdotL, 0.0)));
#elif defined(VIEW_PCSS_BLOCKER)
  o_color = encodeOutput(dbg.blocker < 0.0 ? vec3(0.0, 0.15, 0.0) : vec3(dbg.blocker));
#elif defined(VIEW_PCSS_PENUMBRA)
  o_color = encodeOutput(vec3(clamp(dbg.penumbra / 32.0, 0.0, 1.0), clamp(dbg.penumbra / 8.0, 0.0, 1.0), 0.2));
#else
  vec3 albedo = u_baseColor.rgb;
  vec3 color = albedo * u_ambient + blinnPhong(keyE * keyVis, keyNdotL, N, toLightDir(KEY_TYPE, u_key, P), V, albedo);
#ifdef FILL_LIGHT
  float fillNdotL;
  vec3 fillE = irradiance(LIGHT_SPOT, u_fill, u_fillPower, P, N, fillNdotL);
  float fillVis = 1.0;
#ifdef FILL_CASTS
  ShadowDebug fillDbg;
  fillVis = visibility(LIGHT_SPOT, u_fill, u_fillMap, u_noCube, u_fillCmp, u_noCmpCube, P, N, fillDbg);
#endif
  color += blinnPhong(fillE * fillVis, fillNdotL, N, toLightDir(LIGHT_SPOT, u_fill, P), V, albedo);
#endif
  o_color = encodeOutput(color);
#endif
}
