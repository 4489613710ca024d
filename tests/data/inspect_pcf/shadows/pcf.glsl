// A PCF grid that starts at the receiver instead of being centred on it (offsets 0..4, not -2..2):
// the inspector marks the line whose values leave the solution's (tests/CMakeLists.txt: cli.inspect_*).
// Percentage-closer filtering (Reeves et al. 1987): the lit fraction of PCF_SIZE x PCF_SIZE depth
// comparisons on a grid of whole texels centred on the receiver. Each comparison is tapCompare()
// of shadow_filters.glsl, which includes this file: a tap at offset o (in texels) is lit when the
// receiver's depth there, less the bias, is not behind the depth the map stores there.
float pcf(int type, ShadowLight L, sampler2DArray map, samplerCube cube, ShadowQuery q) {
  float lit = 0.0;
  for (int i = 0; i < PCF_SIZE; ++i)
    for (int j = 0; j < PCF_SIZE; ++j)
      lit += tapCompare(type, L, map, cube, q, vec2(i, j));
  return lit / float(PCF_SIZE * PCF_SIZE);
}
