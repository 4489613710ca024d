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
  // TODO(exercise surface/screen-tbn): begin
  // From dFdx and dFdy of `position` and `uv`: T (where u grows) and the handedness from B (where
  // v grows), T made perpendicular to n and unit; a pixel whose T has no length gets any frame
  // around n (anyPerpendicular). Return mat3(T, cross(n, T) * handedness, n).
  return mat3(anyPerpendicular(n), cross(n, anyPerpendicular(n)), n);
  // TODO(exercise surface/screen-tbn): end
}
