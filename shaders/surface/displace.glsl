// Displacement mapping: the vertex itself moves along its normal by the height field,
//   p' = p + n s (h(uv) - base)
// h in [0, 1] from u_heightMap, s = u_heightScale world units for a height of 1, and base =
// u_heightBase: 1 when the polygon is the top of the field (surface_at = top, parallax's
// convention: mortar sinks in), 0 when it is the bottom (surface_at = bottom, GAMES101's p + n s h:
// bricks stand out). p and n are in object space; n has unit length.
vec3 displacedPosition(vec3 p, vec3 n, vec2 uv) {
  float h = textureLod(u_heightMap, uv, 0.0).r;  // no derivatives in the vertex stages: level 0
  return p + n * (u_heightScale * (h - u_heightBase));
}
