// Texture filtering written out, as the GAMES101 texture lecture derives it. Edit these functions
// in your own shader folder and compare them with the hardware pixel for pixel (in_shader on/off).
//
//   nearestLookup    the texel the sample point falls in
//   bilinearLookup   the four nearest texel centres, two horizontal lerps and one vertical
//   bicubicLookup    sixteen texels, Catmull-Rom weights (what hardware does not offer)
//   levelOfDetail    L = log2(max(|dUV/dx|, |dUV/dy|)), lengths measured in texels of level 0
//                    (mip_level.glsl)
//   filteredLookup   the level(s) chosen from L: level 0 only, the nearest level, or a blend of
//                    the two around L (trilinear, trilinear.glsl); with anisotropy, several probes along the
//                    footprint's long axis (the EXT_texture_filter_anisotropic model)
//
// Texel centres sit at half-integers of uv * size, so a sample at a texel's centre returns that
// texel exactly. Textures repeat (wrapTexel). texel() is the only read of the texture here. Read next: filtering.frag, tutorials/filtering.md.

uniform int u_maxLevel;          // the last level of the texture's chain
uniform float u_lodBias;         // added to L
uniform float u_maxAnisotropy;   // 1: isotropic
#ifdef MANUAL_LEVEL
uniform float u_level;           // L, chosen by hand
#endif

// Repeat: texel -1 is the last one, texel `size` the first. The lookups wrap uv into [0, 1)
// first, so t is never below -size: one addition keeps % away from negative operands (undefined
// in GLSL). Flooring a float quotient instead puts a texel exactly on the edge one period off.
ivec2 wrapTexel(ivec2 t, ivec2 size) { return (t + size) % size; }

// Level `level`'s size: OpenGL's max(1, floor(size / 2^level)).
ivec2 levelSize(sampler2D s, int level) { return max(textureSize(s, 0) >> level, ivec2(1)); }

// One texel of one level, unfiltered. The lab binds a nearest-texel, nearest-level sampler while
// the filter is written here, so a lookup at the texel's centre at a whole level is that texel.
// (texelFetch would say the same more directly, but llvmpipe in Mesa 22 returns texels of the
// wrong level when the level differs within a 2 x 2 pixel quad, which it does where trilinear
// filtering moves from one level to the next: isolated wrong pixels.)
vec4 texel(sampler2D s, ivec2 t, int level) {
  ivec2 size = levelSize(s, level);
  return textureLod(s, (vec2(wrapTexel(t, size)) + 0.5) / vec2(size), float(level));
}

vec4 nearestLookup(sampler2D s, vec2 uv, int level) {
  return texel(s, ivec2(floor(fract(uv) * vec2(levelSize(s, level)))), level);
}

#include "filtering/bilinear.glsl"  // bilinearLookup()

// Catmull-Rom (Keys, a = -1/2): interpolates the texels, overshoots a little at hard edges.
vec4 catmullRom(float t) {
  float t2 = t * t, t3 = t2 * t;
  return vec4(-0.5 * t3 + t2 - 0.5 * t, 1.5 * t3 - 2.5 * t2 + 1.0, -1.5 * t3 + 2.0 * t2 + 0.5 * t, 0.5 * t3 - 0.5 * t2);
}

vec4 bicubicLookup(sampler2D s, vec2 uv, int level) {
  vec2 p = fract(uv) * vec2(levelSize(s, level)) - 0.5;
  ivec2 i = ivec2(floor(p));
  vec2 f = p - vec2(i);
  vec4 wx = catmullRom(f.x), wy = catmullRom(f.y);
  vec4 sum = vec4(0.0);
  for (int y = 0; y < 4; ++y) {
    vec4 row = vec4(0.0);
    for (int x = 0; x < 4; ++x) row += wx[x] * texel(s, i + ivec2(x - 1, y - 1), level);
    sum += wy[y] * row;
  }
  return clamp(sum, 0.0, 1.0);  // the overshoot would leave the range a texture can hold
}

vec4 levelLookup(sampler2D s, vec2 uv, int level) {
#if defined(FILTER_NEAREST)
  return nearestLookup(s, uv, level);
#elif defined(FILTER_BICUBIC)
  return bicubicLookup(s, uv, level);
#else
  return bilinearLookup(s, uv, level);
#endif
}

// The footprint of this pixel in texels of level 0: where uv moves one pixel right (dx) and one
// pixel up (dy). Zero on a constant uv, huge at the horizon; both are handled below.
void footprint(vec2 uv, sampler2D s, out vec2 dx, out vec2 dy) {
  vec2 size0 = vec2(textureSize(s, 0));
  dx = dFdx(uv) * size0;
  dy = dFdy(uv) * size0;
}

#include "filtering/mip_level.glsl"  // levelOfDetail()

// How many probes and at what level the anisotropic filter takes (EXT_texture_filter_anisotropic):
// N = min(ceil(Pmax / Pmin), max anisotropy) probes of a footprint Pmax / N across.
void anisotropicProbes(vec2 dx, vec2 dy, out int n, out float lod, out vec2 axis) {
  float px = length(dx), py = length(dy);
  float pmax = max(px, py), pmin = min(px, py);
  float ratio = pmax / max(pmin, 1e-8);
  n = int(clamp(ceil(ratio), 1.0, max(u_maxAnisotropy, 1.0)));
  lod = log2(max(pmax, 1e-8) / float(n));
  axis = px >= py ? dx : dy;  // in texels of level 0
}

// The level the configured filter reads at (before rounding), clamped to the chain. dx and dy are
// footprint()'s, which the anisotropic filter takes its probes from.
float selectedLevel(sampler2D s, vec2 uv, vec2 dx, vec2 dy) {
#if defined(MANUAL_LEVEL)
  float lod = u_level;
#else
  float lod = levelOfDetail(s, uv);
  if (u_maxAnisotropy > 1.0) {
    int n;
    vec2 axis;
    anisotropicProbes(dx, dy, n, lod, axis);
  }
  lod += u_lodBias;
#endif
  if (isnan(lod)) lod = 0.0;  // 0 / 0 derivatives: a degenerate triangle
  return clamp(lod, 0.0, float(u_maxLevel));
}

#include "filtering/trilinear.glsl"  // trilinearLookup()

vec4 mipLookup(sampler2D s, vec2 uv, float lod) {
#if defined(MIP_NONE)
  return levelLookup(s, uv, 0);
#elif defined(MIP_NEAREST)
  // The spec's rounding: level ceil(L + 1/2) - 1, so L = 0.5 reads level 0.
  return levelLookup(s, uv, int(max(ceil(lod + 0.5) - 1.0, 0.0)));
#else
  return trilinearLookup(s, uv, lod);
#endif
}

vec4 filteredLookup(sampler2D s, vec2 uv) {
  vec2 dx, dy;
  footprint(uv, s, dx, dy);
  float lod = selectedLevel(s, uv, dx, dy);
#if !defined(MIP_NONE) && !defined(MANUAL_LEVEL)
  if (u_maxAnisotropy > 1.0) {
    int n;
    float unused;
    vec2 axis;
    anisotropicProbes(dx, dy, n, unused, axis);
    vec2 step = axis / vec2(textureSize(s, 0));  // back to uv
    vec4 sum = vec4(0.0);
    for (int i = 0; i < n; ++i) sum += mipLookup(s, uv + step * ((float(i) + 0.5) / float(n) - 0.5), lod);
    return sum / float(n);
  }
#endif
  return mipLookup(s, uv, lod);
}
