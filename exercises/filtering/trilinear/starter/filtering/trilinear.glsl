// Trilinear filtering: the two levels around L, each filtered within the level (levelLookup: the
// lab's nearest, bilinear or bicubic), blended by L's fractional part, so the picture changes
// smoothly where the footprint grows from one level's texels to the next's. Included by
// filter.glsl; L arrives clamped to [0, u_maxLevel], the last level of the chain.
vec4 trilinearLookup(sampler2D s, vec2 uv, float lod) {
  // TODO(exercise filtering/trilinear): begin
  // The two levels around lod: l0 = floor(lod) and the next one, no further than u_maxLevel. Read
  // each with levelLookup(s, uv, level) and blend them by how far lod lies past l0.
  return levelLookup(s, uv, 0);
  // TODO(exercise filtering/trilinear): end
}
