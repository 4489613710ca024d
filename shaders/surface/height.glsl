// The height field and what is made of it: a normal by finite differences (bump mapping), and
// texture coordinates shifted as if the surface had depth (the parallax family).
//
// Heights are in [0, 1]. `u_heightScale` world units of relief; `scale` (per fragment) the world
// length of one unit of u and of v, so a depth of s world units is s / scale in UV units.
// Parallax mapping assumes the surface is at the top of the height field and reads depth 1 - h.

uniform sampler2D u_heightMap;
uniform vec2 u_heightTexel;     // 1 / size of the height map
uniform float u_heightScale;    // world units for a height of 1

// The pixel's mip level, taken once where control flow is uniform: the parallax loops run a
// different number of times per pixel, and implicit derivatives inside them are undefined. The
// height field is sampled trilinearly (the lab binds such a sampler), so one level is all its
// footprint needs, and an explicit level is cheaper per read than gradients.
float g_heightLod;
// The level heightAt() reads: the pixel's, or while a parallax march looks for where a ray meets
// the field, the nearest whole level (readNearestLevel). A whole level is one bilinear read where
// a fractional one blends two: on llvmpipe, which skips the second only when no pixel of a block
// needs it, the default POM frame at 1280 x 720 costs a fifth less, and its error against the
// truth moves by 0.3 % (2 % at 192 x 108; tutorials/surface.md, section 8). The normal is taken
// at the pixel's own level again.
float g_readLod;
#ifdef SHADELAB_ES
// GLSL ES 3.00 has no textureQueryLod: the level from the footprint's longer side, as the
// hardware's isotropic selection does (OpenGL 4.6, 8.14.1), clamped to the full mip chain.
float footprintLevel(vec2 uv) {
  vec2 size = vec2(textureSize(u_heightMap, 0)), texels = uv * size;
  float rho = max(length(dFdx(texels)), length(dFdy(texels)));
  return clamp(log2(max(rho, 1e-8)), 0.0, floor(log2(max(size.x, size.y))));  // a full chain
}
#else
float footprintLevel(vec2 uv) { return textureQueryLod(u_heightMap, uv).y; }
#endif

void initHeightGradients(vec2 uv) {
  g_heightLod = footprintLevel(uv);
  g_readLod = g_heightLod;
}

void readNearestLevel(bool nearest) { g_readLod = nearest ? floor(g_heightLod + 0.5) : g_heightLod; }

float heightAt(vec2 uv) { return textureLod(u_heightMap, uv, g_readLod).r; }

// Bump mapping, tangent-space normal. GAMES101 (assignment 3): forward differences one texel apart,
// dU = kh kn (h(u + 1/w, v) - h(u, v)): kh and kn are free, so the result agrees with the
// displaced surface only if kh kn happens to equal s w / (world per UV). The consistent form uses
// central differences and the fragment's own UV scale, and agrees by construction.
vec3 bumpNormalGames101(vec2 uv, float kh, float kn) {
  float h = heightAt(uv);
  float dU = kh * kn * (heightAt(uv + vec2(u_heightTexel.x, 0.0)) - h);
  float dV = kh * kn * (heightAt(uv + vec2(0.0, u_heightTexel.y)) - h);
  return normalize(vec3(-dU, -dV, 1.0));
}

#include "surface/bump.glsl"  // the consistent form: heightNormal()

// The view direction in tangent space, towards the eye; its z is clamped so a grazing ray cannot
// push the lookup to infinity (beyond about 87 degrees from the normal the shift stops growing).
vec3 grazingSafe(vec3 v) { return vec3(v.xy, max(v.z, 0.05)); }

// UV shift per unit of depth along the view ray.
vec2 parallaxDirection(vec3 viewTs, vec2 scale) {
  vec3 v = grazingSafe(viewTs);
  return v.xy / v.z * (u_heightScale / max(scale, vec2(1e-8)));
}

// Parallax mapping (Kaneko et al. 2001): one step, as if the depth at uv held everywhere.
vec2 parallaxOffset(vec2 uv, vec3 viewTs, vec2 scale, out float depth) {
  depth = 1.0 - heightAt(uv);
  return uv - parallaxDirection(viewTs, scale) * depth;
}

#include "surface/parallax_march.glsl"  // steep parallax and POM: parallaxMarch()

// Self-shadowing: from the point found (at `depth`), march towards the light; any height field
// above the ray shadows it. Returns 1 lit .. 0 shadowed (soft: how far above the ray it rose).
float parallaxShadow(vec2 uv, float depth, vec3 lightTs, vec2 scale, int layers) {
  if (lightTs.z <= 0.0) return 0.0;
  float layerDepth = depth / float(max(layers / 2, 1));
  vec2 step = parallaxDirection(lightTs, scale) * layerDepth;
  float current = depth - layerDepth;
  vec2 at = uv + step;
  float worst = 0.0;
  for (int i = 0; i < layers / 2 && current > 0.0; ++i) {
    worst = max(worst, current - (1.0 - heightAt(at)));
    at += step;
    current -= layerDepth;
  }
  return 1.0 - clamp(worst * 8.0, 0.0, 1.0);
}

// The truth's shadow: the exact visibility of the height field from the point at (uv, depth),
// marched towards the light in steps of half a texel (at most 1024), hard; the truth's jittered
// frames antialias its edge. The light direction is not clamped as the view's is above: it is a
// reference, and a grazing light only costs it more steps.
float heightFieldVisibility(vec2 uv, float depth, vec3 lightTs, vec2 scale) {
  if (lightTs.z <= 0.0) return 0.0;
  if (depth <= 0.0) return 1.0;
  vec2 shift = lightTs.xy / max(lightTs.z, 1e-4) * (u_heightScale / max(scale, vec2(1e-8))) * depth;
  int steps = int(clamp(ceil(2.0 * length(shift / u_heightTexel)), 1.0, 1024.0));
  for (int i = 1; i <= steps; ++i) {
    float t = float(i) / float(steps);
    if (1.0 - heightAt(uv + shift * t) < depth * (1.0 - t) - 1e-3) return 0.0;
  }
  return 1.0;
}
