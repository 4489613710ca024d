// Bilinear interpolation in one level: the four texel centres around uv (centres sit at
// (i + 0.5) / size), the fractions of the way to the next centres, two lerps along x and one along
// y. Included by filter.glsl: texel(s, ivec2, level) reads one texel (it wraps) and
// levelSize(s, level) is the level's size in texels.
vec4 bilinearLookup(sampler2D s, vec2 uv, int level) {
  // TODO(exercise filtering/bilinear): begin
  // Bilinear interpolation of the four texel centres around uv in level `level`: find the texel
  // centre below and to the left of uv (centres sit at (i + 0.5) / size), the fractions (s, t)
  // of the way to the next centres, then two lerps along x and one along y. texel(s, ivec2, level)
  // reads one texel (it wraps), levelSize(s, level) is the level's size in texels.
  return nearestLookup(s, uv, level);
  // TODO(exercise filtering/bilinear): end
}
