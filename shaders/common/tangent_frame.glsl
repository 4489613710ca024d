// Tangent frames: the basis in which a normal map's and a height field's directions are given.
//   T along +u, B along +v, N the surface normal; a tangent-space vector t becomes T t.x + B t.y + N t.z.
// From per-vertex tangents (xyz, w = handedness: B = cross(N, T) w), made orthonormal again after
// interpolation (Gram-Schmidt), or from screen-space derivatives of the position and UV (a frame
// per pixel, no tangents needed: Schueler, "Followup: Normal mapping without precomputed tangents",
// 2013). Degenerate inputs (zero-area UVs, a collapsed triangle) fall back to some orthonormal
// frame around N, never to NaN.

vec3 anyPerpendicular(vec3 n) {
  vec3 axis = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  return normalize(cross(axis, n));
}

// `orthogonalize` false leaves the interpolated tangent as it is (a wrong step the lab can show);
// `renormalize` false skips the normalisations (another).
mat3 vertexFrame(vec3 normal, vec4 tangent, bool orthogonalize, bool renormalize) {
  vec3 n = renormalize ? normalize(normal) : normal;
  vec3 t = tangent.xyz;
  if (orthogonalize) t -= n * dot(n, t);
  float len = length(t);
  if (!(len > 1e-8)) {
    t = anyPerpendicular(n);
  } else if (renormalize || orthogonalize) {
    t /= len;
  }
  float w = tangent.w < 0.0 ? -1.0 : 1.0;
  return mat3(t, cross(n, t) * w, n);
}

#include "common/screen_tangent_frame.glsl"  // screenSpaceFrame()
