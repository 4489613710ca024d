// Texel centres at the halves, not shifted by half a texel (docs/grading.md's figures).
// Bilinear interpolation in one level: the four texel centres around uv (centres sit at
// (i + 0.5) / size), the fractions of the way to the next centres, two lerps along x and one along
// y. Included by filter.glsl: texel(s, ivec2, level) reads one texel (it wraps) and
// levelSize(s, level) is the level's size in texels.
vec4 bilinearLookup(sampler2D s, vec2 uv, int level) {
  vec2 p = fract(uv) * vec2(levelSize(s, level));
  ivec2 i = ivec2(floor(p));
  vec2 f = p - vec2(i);
  vec4 u00 = texel(s, i, level), u10 = texel(s, i + ivec2(1, 0), level);
  vec4 u01 = texel(s, i + ivec2(0, 1), level), u11 = texel(s, i + ivec2(1, 1), level);
  vec4 u0 = mix(u00, u10, f.x);  // lerp along x, below ...
  vec4 u1 = mix(u01, u11, f.x);  // ... and above
  return mix(u0, u1, f.y);       // then along y
}
