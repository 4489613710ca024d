// Shared output encoding. Labs compute in linear light and hand the result to encodeOutput(),
// which writes display-encoded sRGB into the float target. NaN and Inf are passed through
// untouched, so the stability scans (shadelab stress) see them instead of a clamped 1.0.

vec3 linearToSrgb(vec3 c) {
  vec3 lo = c * 12.92;
  vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
  return mix(lo, hi, greaterThan(c, vec3(0.0031308)));
}

vec4 encodeOutput(vec3 linearColor) {
  bvec3 bad = bvec3(isnan(linearColor).x || isinf(linearColor).x,
                    isnan(linearColor).y || isinf(linearColor).y,
                    isnan(linearColor).z || isinf(linearColor).z);
  vec3 display = linearToSrgb(clamp(linearColor, 0.0, 1.0));
  return vec4(mix(display, linearColor, bad), 1.0);
}
