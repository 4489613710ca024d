#version 330 core
// Shadows lab, camera pass: Blinn-Phong from a key light (directional, spot or point, chosen by
// KEY_TYPE) and an optional spot fill light, each shadowed through its own map; or one of the
// diagnostic views (visibility, bias heat map, texel density, PCSS blocker depth and penumbra,
// cascades). A directional key light may be split into CASCADE_COUNT cascades, each a map of its
// own fitted to a slice of the view; a blend band hides the seams between them.
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
uniform sampler2DArray u_keyMap;
uniform samplerCube u_keyCube;
uniform sampler2DArrayShadow u_keyCmp;
uniform samplerCubeShadow u_keyCmpCube;
#ifdef FILTER_MOMENTS
uniform sampler2DArray u_keyMoments;
#endif
#ifdef CASCADE_COUNT
// Every cascade is the first one's orthographic box (u_key) moved and scaled in the light's view
// plane: one light direction, one depth range. So a cascade is four numbers, u_cascadeBox[i] =
// (s, t.x, t.y, half width), with clip_i.xy = s clip_1.xy + t: one vec4 read per pixel for the
// cascade it picked, where a whole ShadowLight per cascade, indexed per pixel, cost llvmpipe as
// much as the rest of the lighting pass together.
uniform vec4 u_cascadeBox[CASCADE_COUNT];
uniform float u_cascadeFar[CASCADE_COUNT];    // view depth where cascade i hands over to i + 1
uniform float u_blendFrom[CASCADE_COUNT];     // view depth where blending into i + 1 begins
uniform vec3 u_viewForward;

ShadowLight cascadeLight(int i) {
  vec4 box = u_cascadeBox[i];
  ShadowLight L = u_key;
  L.viewProj[0].xy *= box.x;
  L.viewProj[1].xy *= box.x;
  L.viewProj[2].xy *= box.x;
  L.viewProj[3].xy = L.viewProj[3].xy * box.x + box.yz;
  L.halfWidth = box.w;
  L.layer = float(i);
  return L;
}
#endif
#ifdef FILL_LIGHT
uniform ShadowLight u_fill;
uniform vec3 u_fillPower;
uniform sampler2DArray u_fillMap;
uniform sampler2DArrayShadow u_fillCmp;
uniform samplerCube u_noCube;             // the fill light is a spot: never sampled
uniform samplerCubeShadow u_noCmpCube;
#ifdef FILTER_MOMENTS
uniform sampler2DArray u_fillMoments;
#endif
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

// The gap between the receiver and the depth stored for it, in units of the bias: the surface
// itself stores a gap near 0 (green), lit only thanks to the bias as the gap nears it (yellow,
// orange), acne beyond it (red). A gap of many texels is a real occluder: a shadow (grey).
vec3 heatColor(ShadowDebug d) {
  if (d.gap > 8.0 && d.heat > 1.0) return vec3(0.22);
  if (d.heat > 1.0) return vec3(1.0, 0.08, 0.05);
  float t = clamp(d.heat, -1.0, 1.0);
  return t < 0.0 ? mix(vec3(0.15, 0.75, 0.25), vec3(0.1, 0.3, 1.0), -t)
                 : mix(vec3(0.15, 0.75, 0.25), vec3(1.0, 0.75, 0.05), t);
}

// The key light's shadow term for the chosen filter.
float keyShadow(ShadowLight L, ShadowSurface s, out ShadowDebug dbg) {
#ifdef FILTER_MOMENTS
  return momentVisibility(KEY_TYPE, L, u_keyMoments, s, dbg);
#else
  return visibility(KEY_TYPE, L, u_keyMap, u_keyCube, u_keyCmp, u_keyCmpCube, s, dbg);
#endif
}

void main() {
  vec3 N = normalize(gl_FrontFacing ? v_normal : -v_normal);
  vec3 P = v_worldPos;
  vec3 V = normalize(u_eye - P);
  ShadowSurface surface = shadowSurface(P, N);
  float keyNdotL;
  vec3 keyE = irradiance(KEY_TYPE, u_key, u_keyPower, P, N, keyNdotL);
  bool valid = keyNdotL > 0.0 && max(keyE.r, max(keyE.g, keyE.b)) > 0.0;

  ShadowDebug dbg;
  dbg.heat = 0.0;
  dbg.gap = 0.0;
  dbg.blocker = -1.0;
  dbg.penumbra = 0.0;
  float keyVis = 1.0;
  int cascade = 0;  // the cascade whose map this pixel reads
#ifdef KEY_CASTS
#ifdef CASCADE_COUNT
  // The cascade is the slice the pixel's view depth falls in. The last stretch of each slice (the
  // blend band) hands over to the next cascade, which covers it too: a share of its pixels that
  // grows across the band, picked per pixel by a dither (interleaved gradient noise), reads the
  // next map. One lookup per pixel, never two blended: llvmpipe runs both sides of every branch,
  // so a second lookup "only inside the band" costs it a second lookup everywhere.
  float viewDepth = dot(P - u_eye, u_viewForward);
  float bandFrom = u_blendFrom[0], bandTo = u_cascadeFar[0];
  for (int i = 0; i < CASCADE_COUNT - 1; ++i) {  // constant indices: no per-pixel array reads
    if (viewDepth > u_cascadeFar[i]) {
      cascade = i + 1;
      bandFrom = u_blendFrom[i + 1];
      bandTo = u_cascadeFar[i + 1];
    }
  }
  float handOver = clamp((viewDepth - bandFrom) / max(bandTo - bandFrom, 1e-30), 0.0, 1.0);
  if (cascade < CASCADE_COUNT - 1 && handOver > pixelNoise()) cascade += 1;
  keyVis = keyShadow(cascadeLight(cascade), surface, dbg);
#else
  keyVis = keyShadow(u_key, surface, dbg);
#endif
#endif

#if defined(VIEW_VISIBILITY)
  o_color = vec4(vec3(keyVis), valid ? 1.0 : 0.0);  // data, not a picture: no sRGB encoding
#elif defined(VIEW_POSITION)
  o_color = vec4(P, valid ? 1.0 : 0.0);
#elif defined(VIEW_NORMAL)
  o_color = vec4(N, valid ? 1.0 : 0.0);
#elif defined(VIEW_BIAS_HEAT)
  o_color = encodeOutput(valid ? heatColor(dbg) : vec3(0.05));
#elif defined(VIEW_TEXEL_DENSITY)
  // log2(shadow texel / screen pixel) on the surface: green = matched, red = the map is coarser
  // than the screen (jagged edges), blue = finer (wasted texels).
  float pixelWorld = max(length(fwidth(P)), 1e-30);
#ifdef CASCADE_COUNT
  ShadowLight T = cascadeLight(cascade);
#else
  ShadowLight T = u_key;
#endif
  float ratio = log2(max(texelWorldAt(KEY_TYPE, T, lightDepth(KEY_TYPE, T, P)), 1e-30) / pixelWorld);
  vec3 c = ratio > 0.0 ? mix(vec3(0.2, 0.8, 0.2), vec3(1.0, 0.1, 0.1), clamp(ratio / 3.0, 0.0, 1.0))
                       : mix(vec3(0.2, 0.8, 0.2), vec3(0.1, 0.2, 1.0), clamp(-ratio / 3.0, 0.0, 1.0));
  o_color = encodeOutput(c * (0.35 + 0.65 * max(keyNdotL, 0.0)));
#elif defined(VIEW_CASCADES)
  // One colour per cascade (the blend band a dither of two: each pixel reads one map); magenta
  // where a pixel falls outside the map it reads (a gap in the cover: there must be none).
  const vec3 colours[4] = vec3[4](vec3(0.9, 0.3, 0.25), vec3(0.3, 0.8, 0.3), vec3(0.3, 0.5, 1.0), vec3(0.95, 0.8, 0.2));
#ifdef CASCADE_COUNT
  ShadowLight C = cascadeLight(cascade);
#else
  ShadowLight C = u_key;
#endif
  vec4 clip = C.viewProj * vec4(P, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  bool outside = any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)));
  vec3 c = colours[cascade] * (0.45 + 0.55 * keyVis);
  o_color = encodeOutput(outside && KEY_TYPE == LIGHT_DIRECTIONAL ? vec3(1.0, 0.0, 1.0) : c);
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
#ifdef FILTER_MOMENTS
  fillVis = momentVisibility(LIGHT_SPOT, u_fill, u_fillMoments, surface, fillDbg);
#else
  fillVis = visibility(LIGHT_SPOT, u_fill, u_fillMap, u_noCube, u_fillCmp, u_noCmpCube, surface, fillDbg);
#endif
#endif
  color += blinnPhong(fillE * fillVis, fillNdotL, N, toLightDir(LIGHT_SPOT, u_fill, P), V, albedo);
#endif
  o_color = encodeOutput(color);
#endif
}
