// Displacement mapping: the vertex itself moves along its normal by the height field,
//   p' = p + n s (h(uv) - base)
// h in [0, 1] from u_heightMap, s = u_heightScale world units for a height of 1, and base =
// u_heightBase: 1 when the polygon is the top of the field (surface_at = top, parallax's
// convention: mortar sinks in), 0 when it is the bottom (surface_at = bottom, GAMES101's p + n s h:
// bricks stand out). p and n are in object space; n has unit length.
//
// With displaced_normals = per-vertex the vertex's normal is the displaced surface's too, from the
// height field's slope: with T the unit direction in which u grows (tangent.xyz), B = cross(n, T)
// times the handedness tangent.w, scale the length of one unit of u and of v, and the slopes by
// central differences `texel` apart (one texel of the map),
//   n' = normalize(n - s (dh/du / scale.x) T - s (dh/dv / scale.y) B)
// The vertex stages have no screen-space derivatives: read the map at an explicit level (0).
// TODO(exercise surface/displacement): begin
vec3 displacedPosition(vec3 p, vec3 n, vec2 uv) {
  return p;  // not moved: a flat wall
}

vec3 displacedNormal(vec3 n, vec4 tangent, vec2 uv, vec2 scale, vec2 texel) {
  return n;  // the base mesh's normal
}
// TODO(exercise surface/displacement): end
