// The specular factor s of a point light, raised to the shininess by lighting.glsl: Blinn-Phong's
// s = max(0, N.H), with H the unit vector halfway between the directions to the light (L) and to
// the eye (V), or Phong's s = max(0, R.V) with R the light's mirror direction. N, L and V are unit
// vectors; safeNormalize() (lighting.glsl, which includes this file) guards the half vector, which
// is zero when the light and the eye are exactly opposite.
float specularFactor(vec3 N, vec3 L, vec3 V) {
#ifdef SPECULAR_PHONG
  return max(dot(reflect(-L, N), V), 0.0);
#else
  return max(dot(N, safeNormalize(L + V, N)), 0.0);
#endif
}
