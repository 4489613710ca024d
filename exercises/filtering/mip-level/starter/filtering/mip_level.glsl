// The level of detail L: how far the texture coordinates move across one pixel, measured in texels
// of level 0, and the level whose texels are that large (GAMES101, lecture 9; the OpenGL spec's
// scale factor rho):
//   L = log2(rho),  rho = max(|dUV/dx|, |dUV/dy|),  dUV/dx = dFdx(uv) * the texture's size
// -inf for a constant uv and large at the horizon: selectedLevel() in filter.glsl, which includes
// this file, clamps L to the chain.
float levelOfDetail(sampler2D s, vec2 uv) {
  // TODO(exercise filtering/mip-level): begin
  // How far uv moves across one pixel to the right (dFdx) and one pixel up (dFdy), in texels of
  // level 0 (textureSize(s, 0)); rho, the longer of those two steps; L = log2(rho).
  return 0.0;
  // TODO(exercise filtering/mip-level): end
}
