// Normal mapping: the map stores a unit normal in the surface's tangent frame as a colour,
// c = n * 0.5 + 0.5 per channel. Decoded back to [-1, 1], its x and y scaled by the strength
// (u_normalStrength) and y by the map's green convention (u_greenSign: +1 OpenGL, +Y along +v;
// -1 DirectX), taken into world space by the tangent frame tbn = mat3(T, B, N), and made unit
// length again (an interpolated frame or a scaled map is not unit). A texel that decodes to zero
// has no direction: the surface's own normal stands in. Included by surface.frag.
vec3 normalFromMap(mat3 tbn, vec3 c) {
  // TODO(exercise surface/normal-map): begin
  // Decode the texel c to a tangent-space vector in [-1, 1]; scale its x and y by u_normalStrength
  // and its y by u_greenSign; take it to world space with tbn (columns T, B, N); return it unit
  // length, or tbn[2] where it has none.
  return tbn[2];
  // TODO(exercise surface/normal-map): end
}
