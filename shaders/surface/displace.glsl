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
vec3 displacedPosition(vec3 p, vec3 n, vec2 uv) {
  float h = textureLod(u_heightMap, uv, 0.0).r;
  return p + n * (u_heightScale * (h - u_heightBase));
}

vec3 displacedNormal(vec3 n, vec4 tangent, vec2 uv, vec2 scale, vec2 texel) {
  vec3 T = normalize(tangent.xyz - n * dot(n, tangent.xyz));
  vec3 B = cross(n, T) * tangent.w;
  float dhdu = (textureLod(u_heightMap, uv + vec2(texel.x, 0.0), 0.0).r -
                textureLod(u_heightMap, uv - vec2(texel.x, 0.0), 0.0).r) / (2.0 * texel.x);
  float dhdv = (textureLod(u_heightMap, uv + vec2(0.0, texel.y), 0.0).r -
                textureLod(u_heightMap, uv - vec2(0.0, texel.y), 0.0).r) / (2.0 * texel.y);
  vec2 slope = u_heightScale * vec2(dhdu, dhdv) / max(scale, vec2(1e-8));
  return normalize(n - slope.x * T - slope.y * B);
}
