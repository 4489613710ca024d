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
  // TODO(exercise shadows/shadow-lookup): begin
  // Project P into the light's map, read the depth stored there, and compare it with the
  // receiver's (less the bias) in one space. Then the two places where the map knows nothing.
  return 1.0;
  // TODO(exercise shadows/shadow-lookup): end
}
