// Perspective-correct interpolation, written out. The rasteriser is asked to interpolate three
// numbers per vertex *linearly in screen space* (as `noperspective` does), and the texture
// coordinate at a pixel is made from what it hands back:
//   screenLinearUV(uv, clip)   vertex stage: what to interpolate, from the vertex's texture
//                              coordinate and its clip-space position (clip.w: depth from the eye)
//   perspectiveUV(s)           fragment stage: the pixel's texture coordinate, from s, those three
//                              numbers interpolated linearly across the screen
// Both stages include this file.
vec3 screenLinearUV(vec2 uv, vec4 clip) {
  // Along a triangle seen in perspective, a/w and 1/w vary linearly on the screen; a does not.
  return vec3(uv, 1.0) / clip.w;
}

vec2 perspectiveUV(vec3 s) {
  return s.xy / s.z;  // (uv/w) / (1/w)
}
