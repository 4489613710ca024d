// Normal mapping: the map stores a unit normal in the surface's tangent frame as a colour,
// c = n * 0.5 + 0.5 per channel. Decoded back to [-1, 1], its x and y scaled by the strength
// (u_normalStrength) and y by the map's green convention (u_greenSign: +1 OpenGL, +Y along +v;
// -1 DirectX), taken into world space by the tangent frame tbn = mat3(T, B, N), and made unit
// length again (an interpolated frame or a scaled map is not unit). A texel that decodes to zero
// has no direction: the surface's own normal stands in. Included by surface.frag.
vec3 normalFromMap(mat3 tbn, vec3 c) {
  vec3 nTs = vec3((2.0 * c.xy - 1.0) * u_normalStrength * vec2(1.0, u_greenSign), 2.0 * c.z - 1.0);
  vec3 n = tbn * nTs;
  float len = length(n);
  return len > 1e-6 ? n / len : tbn[2];
}
