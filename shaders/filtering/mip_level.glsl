// The level of detail L: how far the texture coordinates move across one pixel, measured in texels
// of level 0, and the level whose texels are that large (GAMES101, lecture 9; the OpenGL spec's
// scale factor rho):
//   L = log2(rho),  rho = max(|dUV/dx|, |dUV/dy|),  dUV/dx = dFdx(uv) * the texture's size
// -inf for a constant uv and large at the horizon: selectedLevel() in filter.glsl, which includes
// this file, clamps L to the chain.
float levelOfDetail(sampler2D s, vec2 uv) {
  vec2 size0 = vec2(textureSize(s, 0));
  vec2 dx = dFdx(uv) * size0, dy = dFdy(uv) * size0;
  float rho2 = max(dot(dx, dx), dot(dy, dy));
  return 0.5 * log2(rho2);  // log2(rho) without a square root
}
