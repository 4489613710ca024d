// PCSS's first step, the blocker search (Fernando 2005): the average depth of what lies between the
// receiver and the light, over BLOCKER_COUNT taps of a Poisson disk rotated by `angle` and scaled
// to `searchTexels`; -1 when no tap finds a blocker. Each tap compares against the receiver's plane
// at that tap, as the PCF taps do: against the centre depth a sloped receiver would find itself and
// count as its own blocker. Included by shadow_filters.glsl, whose helpers it uses.
float averageBlockerDepth(int type, ShadowLight L, sampler2DArray map, samplerCube cube, ShadowQuery q,
                          float searchTexels, float angle) {
  float sum = 0.0, count = 0.0;
  // TODO(exercise shadows/pcss-blocker): begin
  // Sum the depths of the blockers found at BLOCKER_COUNT taps, o = rotated(u_blockerDisk[k],
  // angle) * searchTexels (offsets in texels), and count them. A tap holds a blocker when the
  // depth stored there, tapLinear(type, L, map, cube, q, o), is closer to the light than the
  // receiver at that tap, receiverDepth(type, L, q, o), minus the bias q.bias.
  // TODO(exercise shadows/pcss-blocker): end
  return count == 0.0 ? -1.0 : sum / count;
}
