// Percentage-closer filtering (Reeves et al. 1987): the lit fraction of PCF_SIZE x PCF_SIZE depth
// comparisons on a grid of whole texels centred on the receiver. Each comparison is tapCompare()
// of shadow_filters.glsl, which includes this file: a tap at offset o (in texels) is lit when the
// receiver's depth there, less the bias, is not behind the depth the map stores there.
float pcf(int type, ShadowLight L, sampler2DArray map, samplerCube cube, ShadowQuery q) {
  // TODO(exercise shadows/pcf): begin
  // Percentage-closer filtering: the fraction of PCF_SIZE x PCF_SIZE depth comparisons, on a grid
  // of whole texels centred on the receiver, that find the receiver lit. For an offset o in texels:
  //   tapLinear(type, L, map, cube, q, o)   the occluder's depth stored in the map at o
  //   receiverDepth(type, L, q, o)          the receiver's depth at o (its plane, or the centre's)
  //   q.bias                                 the bias in the same units: a receiver is lit when
  //                                          receiver - bias <= occluder
  return 1.0;
  // TODO(exercise shadows/pcf): end
}
