// PCSS's first step, the blocker search (Fernando 2005): the average depth of what lies between the
// receiver and the light, over BLOCKER_COUNT taps of a Poisson disk rotated by `angle` and scaled
// to `searchTexels`; -1 when no tap finds a blocker. Each tap compares against the receiver's plane
// at that tap, as the PCF taps do: against the centre depth a sloped receiver would find itself and
// count as its own blocker. Included by shadow_filters.glsl, whose helpers it uses.
float averageBlockerDepth(int type, ShadowLight L, sampler2DArray map, samplerCube cube, ShadowQuery q,
                          float searchTexels, float angle) {
  float sum = 0.0, count = 0.0;
  for (int k = 0; k < BLOCKER_COUNT; ++k) {
    vec2 o = rotated(u_blockerDisk[k], angle) * searchTexels;
    float d = tapLinear(type, L, map, cube, q, o);
    if (d < receiverDepth(type, L, q, o) - q.bias) {
      sum += d;
      count += 1.0;
    }
  }
  return count == 0.0 ? -1.0 : sum / count;
}
