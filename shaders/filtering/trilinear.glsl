// Trilinear filtering: the two levels around L, each filtered within the level (levelLookup: the
// lab's nearest, bilinear or bicubic), blended by L's fractional part, so the picture changes
// smoothly where the footprint grows from one level's texels to the next's. Included by
// filter.glsl; L arrives clamped to [0, u_maxLevel], the last level of the chain.
vec4 trilinearLookup(sampler2D s, vec2 uv, float lod) {
  int l0 = int(floor(lod));
  int l1 = min(l0 + 1, u_maxLevel);
  return mix(levelLookup(s, uv, l0), levelLookup(s, uv, l1), lod - float(l0));
}
