#version 410 core
// Texture-filtering lab, fragment stage: the texture's colour through the configured filter,
// unlit, so that what differs between two pictures is the filter and nothing else.
//   (hardware)   texture(): the sampler's filter, mip levels, LOD bias and anisotropy (set by the lab)
//   IN_SHADER    the same written out in filter.glsl: texelFetch and arithmetic only
//   FILTER_NEAREST / FILTER_BILINEAR / FILTER_BICUBIC   within a level
//   MIP_NONE / MIP_NEAREST / MIP_LINEAR                 level selection (MIP_LINEAR: trilinear)
//   MANUAL_LEVEL the level chosen by hand instead of from the footprint
// Views: VIEW_SHADED; VIEW_MIP_LEVEL (the level read, one colour per level, blended between two
// for trilinear); VIEW_ANISOTROPY (the footprint's long axis over its short one, 1 slate .. 16
// yellow); PROBE (the raw footprint dUV/dx, dUV/dy in texels: the lab reads one pixel of it).
// Read next: filter.glsl.
#include "common/output.glsl"
#include "filtering/filter.glsl"

in vec2 v_uv;

uniform sampler2D u_map;
uniform vec4 u_baseColor;
#ifdef PROBE_MARKER
uniform vec2 u_probe;  // window pixel of the footprint probe, drawn as a ring
#endif

out vec4 o_color;

vec4 lookup(vec2 uv) {
#if defined(IN_SHADER)
  return filteredLookup(u_map, uv);
#elif defined(MANUAL_LEVEL)
  return textureLod(u_map, uv, u_level);
#elif defined(SHADELAB_ES)
  return texture(u_map, uv, u_lodBias);  // ES samplers have no LOD bias: the same bias, given here
#else
  return texture(u_map, uv);
#endif
}

vec3 levelColor(int level) {
  const vec3 palette[8] = vec3[8](vec3(0.85, 0.2, 0.2), vec3(0.95, 0.6, 0.1), vec3(0.9, 0.9, 0.2), vec3(0.3, 0.8, 0.3),
                                  vec3(0.2, 0.75, 0.85), vec3(0.25, 0.4, 0.95), vec3(0.6, 0.3, 0.9), vec3(0.9, 0.4, 0.75));
  return palette[level % 8];
}

void main() {
  vec2 dx, dy;
  footprint(v_uv, u_map, dx, dy);
#if defined(PROBE)
  o_color = vec4(dx, dy);
  return;
#endif
  vec4 c = lookup(v_uv) * u_baseColor;
  vec3 color = c.rgb;
#if defined(VIEW_MIP_LEVEL)
  float lod = selectedLevel(u_map, v_uv, dx, dy);
#if defined(MIP_NONE)
  lod = 0.0;
#elif defined(MIP_NEAREST)
  lod = max(ceil(lod + 0.5) - 1.0, 0.0);
#endif
  int l0 = int(floor(lod));
  vec3 tint = mix(levelColor(l0), levelColor(l0 + 1), lod - float(l0));
  float luminance = dot(c.rgb, vec3(0.2126, 0.7152, 0.0722));
  color = tint * (0.45 + 0.55 * sqrt(luminance));  // the texture stays readable under the tint
#elif defined(VIEW_ANISOTROPY)
  float px = length(dx), py = length(dy);
  float ratio = max(px, py) / max(min(px, py), 1e-8);
  float t = clamp(log2(max(ratio, 1.0)) / 4.0, 0.0, 1.0);  // 1x .. 16x
  color = mix(vec3(0.12, 0.16, 0.28), vec3(1.0, 0.85, 0.2), t) * (0.6 + 0.4 * sqrt(dot(c.rgb, vec3(0.33))));
#endif
#if defined(PROBE_MARKER)
  float d = length(gl_FragCoord.xy - u_probe);
  if (abs(d - 8.0) < 1.2) color = vec3(1.0, 0.2, 1.0);
#endif
  o_color = encodeOutput(color);
  o_color.a = 1.0;  // covered (the background is cleared to alpha 0)
}
