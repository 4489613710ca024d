// The hard shadow test of a 2D map (directional and spot lights), from the light's own matrices:
// 1.0 where P is lit, 0.0 where the map holds a surface nearer the light.
//   P             the receiver, in world space (moved along its normal by the normal offset)
//   bias          a world length along the light's axis: the receiver counts as that much nearer
//   L.viewProj    world -> the light's clip space: orthographic (directional) or perspective (spot)
//   map, L.layer  the depth the depth pass stored for that projection (window depth, in [0, 1]),
//                 at array layer L.layer
//   L.position, L.axis, L.nearPlane, L.farPlane   the light's eye, its unit axis, its planes
// Outside the map and beyond its far plane nothing was drawn: both are lit.
float shadowLookup(int type, ShadowLight L, sampler2DArray map, vec3 P, float bias) {
  vec4 clip = L.viewProj * vec4(P, 1.0);
  if (clip.w <= 0.0) return 1.0;  // behind a spot light's eye: not on its map
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;  // NDC [-1, 1] -> texture [0, 1]
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
  float receiver = dot(P - L.position, L.axis);  // the light's depth runs along its axis
  if (receiver > L.farPlane) return 1.0;
  // Window depth back to the light's depth: linear for an orthographic projection, the inverse of
  // z = (1/n - 1/d) / (1/n - 1/f) for a perspective one.
  float z = texture(map, vec3(uv, L.layer)).r, n = L.nearPlane, f = L.farPlane;
  float occluder = type == LIGHT_DIRECTIONAL ? mix(n, f, z) : n * f / (f - z * (f - n));
  return receiver - bias > occluder ? 0.0 : 1.0;
}
