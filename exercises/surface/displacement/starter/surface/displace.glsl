// Displacement mapping: the vertex itself moves along its normal by the height field,
//   p' = p + n s (h(uv) - base)
// h in [0, 1] from u_heightMap, s = u_heightScale world units for a height of 1, and base =
// u_heightBase: 1 when the polygon is the top of the field (surface_at = top, parallax's
// convention: mortar sinks in), 0 when it is the bottom (surface_at = bottom, GAMES101's p + n s h:
// bricks stand out). p and n are in object space; n has unit length.
vec3 displacedPosition(vec3 p, vec3 n, vec2 uv) {
  // TODO(exercise surface/displacement): begin
  // Move p along n by the height field (above): read h, subtract the base, scale.
  return p;
  // TODO(exercise surface/displacement): end
}
