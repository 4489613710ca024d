// A tangent frame per pixel from screen-space derivatives (Schueler, "Followup: Normal mapping
// without precomputed tangents", 2013): no tangents in the mesh. Across one pixel the position
// moves dp1 = dFdx(p), dp2 = dFdy(p) and the UV duv1, duv2; the tangent T is the direction in which
// u grows and B the one in which v grows, found in the surface's plane with the vectors
// perpendicular to dp2 and dp1 (solving the 2 x 2 system without inverting it):
//   T ~ cross(dp2, N) duv1.x + cross(N, dp1) duv2.x     B ~ ... the same with .y
// T is made perpendicular to N and unit; B = cross(N, T) times the handedness (mirrored UVs make it
// -1). A pixel whose UVs do not change (a collapsed triangle) has no T: any frame around N, never NaN.
// Included by tangent_frame.glsl (anyPerpendicular).
mat3 screenSpaceFrame(vec3 normal, vec3 position, vec2 uv) {
  vec3 n = normalize(normal);
  vec3 dp1 = dFdx(position), dp2 = dFdy(position);
  vec2 duv1 = dFdx(uv), duv2 = dFdy(uv);
  vec3 dp2perp = cross(dp2, n), dp1perp = cross(n, dp1);
  vec3 t = dp2perp * duv1.x + dp1perp * duv2.x;
  vec3 b = dp2perp * duv1.y + dp1perp * duv2.y;
  t -= n * dot(n, t);
  float lt = length(t);
  if (!(lt > 1e-20)) return mat3(anyPerpendicular(n), cross(n, anyPerpendicular(n)), n);
  t /= lt;
  float w = dot(cross(n, t), b) < 0.0 ? -1.0 : 1.0;
  return mat3(t, cross(n, t) * w, n);
}
