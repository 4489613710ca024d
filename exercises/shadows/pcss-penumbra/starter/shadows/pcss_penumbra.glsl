// PCSS's second step (Fernando 2005): the penumbra's width from the average blocker depth dB and
// the receiver's depth dR by similar triangles, as the size of the PCF filter in texels. A light
// of radius R seen past a blocker at dB spreads its shadow on a receiver at dR over
//   w = R (dR - dB) / dB           on the map plane of a perspective map (spot, point), in
//                                  tangent units after dividing by dR: R (dR - dB) / (dB dR)
//   w = R (dR - dB)                for a directional light, R the tangent of its angular radius
// zero where the blocker touches the receiver. `toTexels` turns map-plane units into texels.
// Included by shadow_filters.glsl.
float penumbraTexels(int type, ShadowLight L, float dR, float dB, float toTexels) {
  // TODO(exercise shadows/pcss-penumbra): begin
  // The penumbra's width by similar triangles from the light's radius L.radius, the receiver's
  // depth dR and the average blocker depth dB (formulas above: one for LIGHT_DIRECTIONAL, one for
  // the perspective maps of spot and point lights), then in texels: times toTexels.
  return 0.0;
  // TODO(exercise shadows/pcss-penumbra): end
}
