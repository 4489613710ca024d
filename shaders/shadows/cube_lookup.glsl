// The hard shadow test of a point light's cube map: 1.0 where P is lit, 0.0 where the map holds a
// surface nearer the light.
//   P       the receiver, in world space (moved along its normal by the normal offset)
//   bias    a world length along the ray from the light: the receiver counts as that much nearer
//   cube    one face per axis; each texel holds the distance from L.position to the nearest
//           surface in its direction, divided by L.farPlane
// Beyond the far plane nothing was drawn: lit.
float cubeShadowLookup(ShadowLight L, samplerCube cube, vec3 P, float bias) {
  vec3 fromLight = P - L.position;  // a cube map is read by direction; its length does not matter
  float receiver = length(fromLight);
  if (receiver > L.farPlane) return 1.0;
  float occluder = texture(cube, fromLight).r * L.farPlane;
  return receiver - bias > occluder ? 0.0 : 1.0;
}
